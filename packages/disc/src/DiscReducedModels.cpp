#include "cyclone/disc/DiscReducedModels.hpp"

#include <Teuchos_Comm.hpp>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>

#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/ContentHash.hpp"
#include "cyclone/mesh/MeshDigest.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/cyclic/CyclicTransform.hpp"
#include "cyclone/cyclic/Prestress.hpp"
#include "cyclone/io/ReducedModelFile.hpp"
#include "cyclone/rom/BoundaryReduction.hpp"
#include "cyclone/rom/CraigBamptonModel.hpp"
#include "cyclone/rom/NodalDiameterModel.hpp"
#include "cyclone/rom/GuyanModel.hpp"

namespace cyclone::disc {

std::string reducedModelKindName(ReducedModelKind kind) {
  switch (kind) {
    case ReducedModelKind::Hybrid: return "hybrid";
    case ReducedModelKind::Truncation: return "truncation";
    case ReducedModelKind::Guyan: return "guyan";
    case ReducedModelKind::CraigBampton: return "craig_bampton";
    case ReducedModelKind::FullFe: return "full_fe";
  }
  return "";
}

ReducedModelKind reducedModelKindFromName(const std::string& name, const std::string& key) {
  for (auto kind : {ReducedModelKind::Hybrid, ReducedModelKind::Truncation, ReducedModelKind::Guyan,
                    ReducedModelKind::CraigBampton, ReducedModelKind::FullFe})
    if (reducedModelKindName(kind) == name) return kind;
  throw InputError(key, "unknown kind '" + name +
                            "' (hybrid: modes + exact static correction; truncation: modes only; guyan; "
                            "craig_bampton: `modes` fixed-interface modes; full_fe: the FE compliance itself, the "
                            "reference)");
}

std::vector<int> nodalDiametersFor(int sectors, int engineOrder, const std::vector<int>& harmonics) {
  std::set<int> nds;
  for (int h : harmonics) {
    const long k = ((long(h) * engineOrder) % sectors + sectors) % sectors;
    nds.insert(int(2 * k > sectors ? sectors - k : k));
  }
  return {nds.begin(), nds.end()};
}

std::vector<int> nodalDiametersForCheckedCurve(int sectors, int engineOrder, const std::vector<int>& harmonics,
                                               int harmonicsCheckTo) {
  auto checked = harmonics;
  const int highest = *std::max_element(harmonics.begin(), harmonics.end());
  for (int h = highest + 1; h <= std::max(highest + 1, harmonicsCheckTo); ++h) checked.push_back(h);
  return nodalDiametersFor(sectors, engineOrder, checked);
}

namespace {

// The prestress as the cache's digests have named it since its first version.
std::string prestressName(cyclic::PrestressKind kind) {
  switch (kind) {
    case cyclic::PrestressKind::None: return "none";
    case cyclic::PrestressKind::Linear: return "linear";
    case cyclic::PrestressKind::Nonlinear: return "nonlinear";
  }
  return "";
}

// Everything a model of one nodal diameter depends on, mesh included.
std::string modelHash(const mesh::Mesh& mesh, const DiscModelSpec& s, int nd) {
  ContentHash h;
  h.add(std::string("cyclone reduced model v1"));
  mesh::addToHash(h, mesh);
  for (const auto& sets : {s.fixedNodeSets, s.leftSets, s.rightSets, s.retainedNodeSets})
    mesh::addNodeSetsToHash(h, mesh, sets);
  h.add(s.material.E).add(s.material.nu).add(s.material.rho);
  // Only when not the default, so that the default's cached results keep their keys.
  if (s.material.massQuadrature != fe::MassQuadrature::Exact) h.add(std::string("mass quadrature: stiffness rule"));
  h.add(s.sectors).add(s.axis.point.data(), sizeof(double) * 3).add(s.axis.direction.data(), sizeof(double) * 3);
  h.add(s.rpm).add(prestressName(s.prestress)).add(reducedModelKindName(s.kind)).add(s.modes).add(s.omega0).add(s.lossFactor).add(nd);
  // Only when there are means, so that the models without them keep their keys.
  for (const auto& m : s.retainedMeans) {
    h.add(std::string("retained mean ") + m.name);
    for (std::size_t i = 0; i < m.nodes.size(); ++i) h.add(static_cast<long long>(mesh.nodeIds.at(std::size_t(m.nodes[i])))).add(m.weights[i]);
  }
  return h.hex();
}

// Natural frequencies in Hz from eigenvalues with pairs listed twice (a pair counts once).
std::vector<double> distinctHz(const std::vector<double>& eigenvalues, int copies) {
  std::vector<double> hz;
  for (std::size_t j = 0; j < eigenvalues.size(); j += std::size_t(copies))
    hz.push_back(std::sqrt(std::max(eigenvalues[j], 0.0)) / (2 * M_PI));
  return hz;
}

// The check file's last line: a digest of the lines above it (the header and rows as
// written), so an edited or damaged check is not quoted as the model's (issue 49).
constexpr const char* kCheckDigest = "# content_digest,";

std::string checkDigest(const std::string& text) { return ContentHash().add(text).hex(); }

// The check of a cached model read back, or none where it does not carry its digest or the
// digest does not match (an edited, damaged or older file): the model is then rebuilt and
// checked again.
std::optional<ReducedModelCheck> readCheck(const std::string& path, int nd, std::string& why) {
  std::ifstream in(path);
  std::string text, line, digest;
  while (std::getline(in, line)) {
    if (line.rfind(kCheckDigest, 0) == 0) {
      digest = line.substr(std::string(kCheckDigest).size());
      break;
    }
    text += line + "\n";
  }
  if (digest.empty()) return why = "it carries no content digest", std::nullopt;
  if (digest != checkDigest(text)) return why = "its content does not match its digest", std::nullopt;
  ReducedModelCheck c;
  std::stringstream lines(text);
  std::getline(lines, line);  // the header
  try {
    while (std::getline(lines, line)) {
      std::stringstream cells(line);
      std::string v[4];
      for (auto& x : v) std::getline(cells, x, ',');
      c.hz.push_back(std::stod(v[0])), c.reduced.push_back(std::stod(v[1]));
      c.full.push_back(std::stod(v[2])), c.error.push_back(std::stod(v[3]));
    }
  } catch (const std::exception&) {
    return why = "a row is not four numbers", std::nullopt;
  }
  c.nodalDiameter = nd;
  return c;
}

}  // namespace

void writeReducedModelCheckCsv(const std::string& path, const ReducedModelCheck& c, bool digest) {
  std::ostringstream rows;
  rows.precision(12);
  rows << "freq_hz,reduced_abs,full_abs,relative_error\n";
  for (std::size_t i = 0; i < c.hz.size(); ++i)
    rows << c.hz[i] << "," << c.reduced[i] << "," << c.full[i] << "," << c.error[i] << "\n";
  const std::string text = digest ? rows.str() + kCheckDigest + checkDigest(rows.str()) + "\n" : rows.str();
  AtomicFile file(path);
  file.write(text.data(), text.size());
  file.commit();
}

double ReducedModelCheck::maxError() const {
  double e = 0;
  for (double x : error) e = std::max(e, x);
  return e;
}

void checkModelCheckFrequencies(int frequencies) {
  if (frequencies < 0 || frequencies > kMaxCheckFrequencies)
    throw InputError("check_frequencies",
                     std::to_string(frequencies) + ": must lie in 0.." + std::to_string(kMaxCheckFrequencies) +
                         " (0: no check; each frequency is a complex factorization of the nodal diameter's full FE "
                         "system, spread from half the first natural frequency to the fifth's)");
}

std::optional<cyclic::PrestressState> discPrestress(const mesh::Mesh& mesh, const cyclic::CyclicSector& sector,
                                                   const DiscModelSpec& spec, linalg::CommPtr comm) {
  if (spec.prestress == cyclic::PrestressKind::None || spec.rpm == 0) return std::nullopt;
  const mesh::RotationAxis& axis = spec.axis;
  const auto k0 = cyclic::cyclicTransform(mesh, sector, 0, spec.fixedNodeSets);
  return spec.prestress == cyclic::PrestressKind::Linear ? cyclic::solveLinearPrestress(mesh, k0, spec.material, spec.rpm, axis, comm)
                                    : cyclic::solveNonlinearPrestress(mesh, k0, spec.material, spec.rpm, axis, comm);
}

std::string reducedModelCachePath(const mesh::Mesh& mesh, const DiscModelSpec& spec, int nodalDiameter,
                                  const std::string& cacheDirectory) {
  return cacheDirectory + "/rom_nd" + std::to_string(nodalDiameter) + "_" +
         modelHash(mesh, spec, nodalDiameter).substr(0, 20) + ".h5";
}

void checkReducedModelCache(const mesh::Mesh& mesh, const DiscModelSpec& spec, const std::vector<int>& nodalDiameters,
                            const std::string& cacheDirectory) {
  namespace fs = std::filesystem;
  if (cacheDirectory.empty() || spec.kind == ReducedModelKind::FullFe) return;
  std::error_code ec;
  if (!fs::exists(cacheDirectory, ec)) return;  // nothing can take a name in it (and no hashing)
  if (!fs::is_directory(cacheDirectory, ec))
    throw InputError("reduced_model/cache", cacheDirectory +
                                                " is not a directory, where the reduced models are kept: move it, or "
                                                "set cache: off");
  for (int k : nodalDiameters) {
    const std::string path = reducedModelCachePath(mesh, spec, k, cacheDirectory);
    if (fs::exists(path, ec) && !fs::is_regular_file(path, ec))
      throw InputError("reduced_model/cache", path + ", the file of nodal diameter " + std::to_string(k) +
                                                  "'s model, is taken by something that is not a file (a directory?): "
                                                  "move it, or set cache: off");
  }
}

namespace {

// A cached model of nodal diameter k read back into `out` (false: none, or damaged and
// to be rebuilt).
bool readCachedModel(const std::string& path, int k, const DiscModelSpec& spec, const std::string& inputs,
                     DiscReducedModels& out) {
  if (path.empty() || !std::filesystem::exists(path)) return false;
  std::optional<io::ReducedModelRecord> cached;
  try {
    cached = io::readReducedModelHdf5(path);
  } catch (const std::exception& e) {
    // Truncated or damaged (a killed copy, a full disk): rebuilt and written again.
    log::warn("reduced model ND " + std::to_string(k) + ": the cached " + path + " cannot be read (" + e.what() +
              "); rebuilding it");
    return false;
  }
  const auto& record = *cached;
  // The file's content must be what it was written with (its digest) and what its name
  // promises: a copied, renamed or edited file is computed again, not trusted.
  std::ostringstream wrong;
  if (!record.contentVerified) wrong << "it carries no content digest (written by an older version)";
  else if (record.kind != reducedModelKindName(spec.kind))
    wrong << "it holds a " << record.kind << " model, " << reducedModelKindName(spec.kind) << " expected";
  else if (record.nodalDiameter != k)
    wrong << "it holds the model of nodal diameter " << record.nodalDiameter << ", " << k << " expected";
  else if (record.sectors != spec.sectors)
    wrong << "it holds a model of " << record.sectors << " sectors, " << spec.sectors << " expected";
  else if (record.rpm != spec.rpm)
    wrong << "it holds a model at " << record.rpm << " rpm, " << spec.rpm << " expected";
  // A valid model of other inputs (another material, mesh or retained set) under this
  // name gave another scene's peak with exit 0 (issue 49's fourth probe).
  else if (record.inputDigest.empty())
    wrong << "it does not say which inputs it was built from (written by an older version)";
  else if (record.inputDigest != inputs)
    wrong << "it was built from other inputs (its input digest " << record.inputDigest.substr(0, 20) << ", this run's "
          << inputs.substr(0, 20) << ")";
  if (!wrong.str().empty()) {
    log::warn("reduced model ND " + std::to_string(k) + ": the cached " + path + " is not reused: " + wrong.str() +
              "; rebuilding it");
    return false;
  }
  // A check asked for and not beside the model (deleted, or the model built without one)
  // was silently missing from the summary (issue 49 probe): the model is checked again.
  if (k == spec.checkNodalDiameter && spec.checkFrequencies > 0 && !std::filesystem::exists(path + ".check.csv")) {
    log::warn("reduced model ND " + std::to_string(k) + ": the cached " + path + " has no check beside it (" + path +
              ".check.csv); rebuilding the model and checking it");
    return false;
  }
  if (k == spec.checkNodalDiameter && std::filesystem::exists(path + ".check.csv")) {
    std::string why;
    const auto check = readCheck(path + ".check.csv", k, why);
    if (!check) {
      log::warn("reduced model ND " + std::to_string(k) + ": the check of the cached " + path + " (" + path +
                ".check.csv) is not reused: " + why + "; rebuilding the model and checking it again");
      return false;
    }
    out.check = *check;
    out.check.reused = true;
    // When it was checked: the check file's modification time, UTC.
    const auto written = std::filesystem::last_write_time(path + ".check.csv");
    const auto system = std::chrono::time_point_cast<std::chrono::system_clock::duration>(
        written - std::filesystem::file_time_type::clock::now() + std::chrono::system_clock::now());
    const std::time_t t = std::chrono::system_clock::to_time_t(system);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", std::gmtime(&t));
    out.check.checkedAt = text;
  }
  // Guyan and Craig-Bampton files carry the full model's natural frequencies computed beside them.
  out.naturalHz[k] = record.kind == "guyan" || record.kind == "craig_bampton"
                         ? distinctHz(record.fullModelEigenvalues, record.reduction.copies)
                         : distinctHz(record.modes.eigenvalues, record.modes.copies);
  if (out.naturalHz[k].empty()) throw InputError(path, "holds no natural frequencies of the full model");
  out.models[k] = record.model();
  out.files[k] = path;
  ++out.reused;
  log::info("reduced model ND " + std::to_string(k) + ": reused " + path + " (inputs unchanged, content verified)");
  return true;
}

// One nodal diameter's reduced model of the spec's kind from its full FE model, and the
// record its cache file holds (none for the full FE model itself).
struct BuiltModel {
  std::shared_ptr<const rom::ComplianceModel> model;
  std::optional<io::ReducedModelRecord> record;
};

BuiltModel reduceModel(const std::shared_ptr<rom::NodalDiameterModel>& full, const rom::RetainedModes& modes, int k,
                       const DiscModelSpec& spec, const std::vector<mesh::Index>& retainedNodes) {
  std::vector<int> nodes, directions, copies;
  // A mean's DOFs are filed under node -1 - m (its definition is in the file's name's hash).
  for (int c = 0; c < full->copies(); ++c) {
    for (auto node : retainedNodes)
      for (int d = 0; d < 3; ++d) nodes.push_back(int(node)), directions.push_back(d), copies.push_back(c);
    for (std::size_t m = 0; m < spec.retainedMeans.size(); ++m)
      for (int d = 0; d < 3; ++d) nodes.push_back(-1 - int(m)), directions.push_back(d), copies.push_back(c);
  }
  BuiltModel out;
  if (spec.kind == ReducedModelKind::FullFe) {
    out.model = full;
  } else if (spec.kind == ReducedModelKind::Guyan || spec.kind == ReducedModelKind::CraigBampton) {
    const auto reduction = rom::reduceOntoRetainedDofs(*full, spec.kind == ReducedModelKind::Guyan ? 0 : spec.modes);
    if (spec.kind == ReducedModelKind::Guyan) {
      const auto guyan = std::make_shared<rom::GuyanModel>(reduction, spec.lossFactor);
      out.model = guyan;
      out.record = io::makeReducedModelRecord(*guyan, k, spec.sectors, spec.rpm, nodes, directions, copies);
    } else {
      const auto cb = std::make_shared<rom::CraigBamptonModel>(reduction, spec.modes, spec.lossFactor);
      out.model = cb;
      out.record = io::makeReducedModelRecord(*cb, k, spec.sectors, spec.rpm, nodes, directions, copies);
    }
    out.record->fullModelEigenvalues = modes.eigenvalues;
  } else {
    // The expansion point named as the scene's key (the message said "omega0: 1e+300 ...").
    const auto staticCompliance = [&] {
      try {
        return full->staticCompliance(spec.omega0, modes);
      } catch (const InputError& e) {
        if (e.where() == "omega0") throw InputError("reduced_model/omega0", e.problem());
        throw;
      }
    };
    const auto hybrid =
        spec.kind == ReducedModelKind::Hybrid
            ? std::make_shared<rom::HybridFrfModel>(modes, staticCompliance(), spec.lossFactor)
            : std::make_shared<rom::HybridFrfModel>(rom::HybridFrfModel::modalTruncation(modes, spec.lossFactor));
    out.model = hybrid;
    out.record = io::makeReducedModelRecord(*hybrid, k, spec.sectors, spec.rpm, nodes, directions, copies);
  }
  return out;
}

// The reduced model against the full FE compliance at spec.checkFrequencies frequencies
// from half the first natural frequency to the fifth's (or the last computed), log-spaced.
// The error per frequency is ||(A_r - A_f) R||_F / ||A_f R||_F over kProbes random
// columns R (fixed seed): for Gaussian R, E ||E R||_F^2 = kProbes ||E||_F^2, so the ratio
// estimates the Frobenius relative error of the whole compliance without a solve per
// retained DOF (at mesh size 3, 1050 solves a frequency made the check eight times the
// model's own time). One more column, the last retained DOF's unit load, gives the
// diagonal entry the check's plot shows.
ReducedModelCheck checkAgainstFull(const rom::ComplianceModel& model, const rom::ComplianceModel& full, int k,
                                   const std::vector<double>& hz, int frequencies) {
  constexpr int kProbes = 8;
  Timer timer;
  const double lo = 0.5 * hz.front(), hi = 1.05 * hz[std::min<std::size_t>(4, hz.size() - 1)];
  const Eigen::Index n = full.size();
  Eigen::MatrixXd probes(n, kProbes + 1);
  std::mt19937_64 random(20261127);
  std::normal_distribution<double> gauss;
  for (Eigen::Index j = 0; j < kProbes; ++j)
    for (Eigen::Index i = 0; i < n; ++i) probes(i, j) = gauss(random);
  probes.col(kProbes).setZero();
  probes(n - 1, kProbes) = 1.0;  // the last retained node's last direction
  ReducedModelCheck c;
  c.nodalDiameter = k;
  for (int i = 0; i < frequencies; ++i) {
    const double f = lo * std::pow(hi / lo, double(i) / std::max(1, frequencies - 1));
    const Eigen::MatrixXcd Ar = model.complianceTimes(2 * M_PI * f, probes);
    Eigen::MatrixXcd Af;
    try {
      Af = full.complianceTimes(2 * M_PI * f, probes);
    } catch (const OutOfMemoryError& e) {
      // The full FE compliance's complex factor of a large sector (the seed's 334k-DOF
      // one) does not fit: the check is a verification, not the answer, so the chain goes
      // on without it and says so.
      c = ReducedModelCheck{};
      c.nodalDiameter = k;
      c.notMade = std::string("its full FE solve ran out of memory (") + e.what() + ")";
      log::warn("reduced model check at ND " + std::to_string(k) + " not made: " + c.notMade +
                "; the model is used unchecked (check_frequencies: 0 skips the attempt)");
      return c;
    }
    c.hz.push_back(f);
    c.reduced.push_back(std::abs(Ar(n - 1, kProbes)));
    c.full.push_back(std::abs(Af(n - 1, kProbes)));
    c.error.push_back((Ar - Af).leftCols(kProbes).norm() / Af.leftCols(kProbes).norm());
  }
  c.seconds = timer.seconds();
  std::ostringstream line;
  line << "reduced model check at ND " << k << ": largest relative error " << c.maxError() << " over " << frequencies
       << " frequencies " << lo << ".." << hi << " Hz (" << kProbes << " random probes, " << c.seconds << " s)";
  log::info(line.str());
  return c;
}

}  // namespace

DiscReducedModels buildDiscReducedModels(const mesh::Mesh& mesh, const DiscModelSpec& spec,
                                         const std::vector<int>& nodalDiameters, const std::string& cacheDirectory,
                                         linalg::CommPtr comm) {
  if (spec.modes < 1) throw InputError("reduced_model/modes", "must be at least 1");
  try {
    checkModelCheckFrequencies(spec.checkFrequencies);
  } catch (const InputError& e) {
    throw InputError("reduced_model/" + e.where(), e.problem());
  }
  if (nodalDiameters.empty()) throw InputError("reduced_model", "no nodal diameters asked for");
  Timer timer;
  DiscReducedModels out;
  out.sectors = spec.sectors;
  out.rpm = spec.rpm;
  out.sector = cyclic::makeCyclicSector(mesh, spec.sectors, spec.axis, spec.leftSets, spec.rightSets);
  for (int k : nodalDiameters) cyclic::checkNodalDiameter(spec.sectors, k);
  for (const auto& name : spec.retainedNodeSets)
    for (mesh::Index n : mesh.nodeSet(name))
      if (std::find(out.retainedNodes.begin(), out.retainedNodes.end(), n) == out.retainedNodes.end())
        out.retainedNodes.push_back(n);

  rom::NodalDiameterModelProblem problem;
  problem.material = spec.material;
  problem.fixedNodeSets = spec.fixedNodeSets;
  problem.retainedNodeSets = spec.retainedNodeSets;
  problem.retainedMeans = spec.retainedMeans;
  out.retainedMeans = spec.retainedMeans;
  problem.lossFactor = spec.lossFactor;
  std::optional<cyclic::PrestressState> prestress;  // computed when the first model is built, not for read-backs
  bool prestressed = false;
  // Every reduced kind has an HDF5 form; the full FE model is the reference and is rebuilt.
  const bool cache = !cacheDirectory.empty() && spec.kind != ReducedModelKind::FullFe;
  if (cache) checkReducedModelCache(mesh, spec, nodalDiameters, cacheDirectory);
  if (cache && comm->getRank() == 0) std::filesystem::create_directories(cacheDirectory);
  for (int k : nodalDiameters) {
    const std::string inputs = modelHash(mesh, spec, k);
    const std::string path = cache ? reducedModelCachePath(mesh, spec, k, cacheDirectory) : std::string();
    if (readCachedModel(path, k, spec, inputs, out)) continue;
    if (!prestressed) {
      prestress = discPrestress(mesh, out.sector, spec, comm);
      prestressed = true;
      if (prestress) problem.prestress = std::make_shared<const cyclic::PrestressState>(std::move(*prestress));
    }
    problem.nodalDiameter = k;
    Timer build;
    auto full = std::make_shared<rom::NodalDiameterModel>(mesh, out.sector, problem, comm);
    const auto modes = full->modes(spec.modes);
    if (modes.numRigidBodyModes() > 0)
      throw InputError("constraints/fixed_node_sets", "the sector has rigid-body modes at ND " + std::to_string(k) +
                                                          ": a disc response needs the disc held (e.g. the bore)");
    out.naturalHz[k] = distinctHz(modes.eigenvalues, modes.copies);
    auto built = reduceModel(full, modes, k, spec, out.retainedNodes);
    if (built.record) built.record->inputDigest = inputs;
    out.models[k] = built.model;
    ++out.built;
    if (k == spec.checkNodalDiameter && spec.kind != ReducedModelKind::FullFe && spec.checkFrequencies > 0) {
      out.check = checkAgainstFull(*built.model, *full, k, out.naturalHz[k], spec.checkFrequencies);
    }
    std::ostringstream msg;
    msg << "reduced model ND " << k << " (" << reducedModelKindName(spec.kind) << ", " << spec.modes
        << " natural frequencies, " << full->size() << " retained DOFs): built in " << build.seconds() << " s; first "
        << out.naturalHz[k].front() << " Hz";
    log::info(msg.str());
    if (cache && built.record) {
      // The model first, then its check beside it: a write that fails (a full disk) leaves
      // neither a check without its model nor a model whose check is half-written.
      if (comm->getRank() == 0) {
        io::writeReducedModelHdf5(path, *built.record);
        if (!out.check.hz.empty() && k == spec.checkNodalDiameter) {
          try {
            writeReducedModelCheckCsv(path + ".check.csv", out.check, true);
          } catch (...) {
            std::error_code ignored;
            std::filesystem::remove(path, ignored);
            throw;
          }
        }
      }
      out.files[k] = path;
    }
  }
  comm->barrier();
  out.seconds = timer.seconds();
  return out;
}

}  // namespace cyclone::disc
