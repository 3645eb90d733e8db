#include "cyclone/scenes/SceneSection.hpp"

#include <Teuchos_Array.hpp>

#include <cctype>
#include <map>
#include <sstream>
#include <vector>

#include "cyclone/core/Error.hpp"
#include "SceneYaml.hpp"

namespace cyclone::scenes {

namespace {
const Teuchos::ParameterList& emptyList() {
  static const Teuchos::ParameterList empty;
  return empty;
}
}  // namespace

namespace {
bool isEmptyList(const Teuchos::ParameterList& list, const std::string& key) {
  return list.isType<std::string>(key) && list.get<std::string>(key) == kEmptyList;
}

// YAML's special floats (.nan, .inf, -.inf in any of their spellings) reach the scene as
// text: said as what they are, not as "got 'string'" (a fifth probe).
std::string specialFloat(const std::string& text) {
  std::string t;
  for (char c : text) t += char(std::tolower(static_cast<unsigned char>(c)));
  if (t == ".nan") return "YAML's not-a-number";
  if (t == ".inf" || t == "+.inf" || t == "-.inf") return "YAML's infinity";
  return "";
}

// Why the value under `key` is not the number(s) asked for.
std::string notNumbers(const Teuchos::ParameterList& list, const std::string& key, const std::string& expected) {
  auto said = [&](const std::string& text) {
    const std::string special = specialFloat(text);
    return special.empty() ? "the text '" + text + "'"
                           : text + " (" + special + "; an input here is a finite number)";
  };
  if (list.isType<std::string>(key)) return "expected " + expected + ", got " + said(list.get<std::string>(key));
  if (list.isType<Teuchos::Array<std::string>>(key)) {
    const auto& a = list.get<Teuchos::Array<std::string>>(key);
    for (std::size_t i = 0; i < std::size_t(a.size()); ++i)
      if (!specialFloat(a[i]).empty())
        return "expected " + expected + ", got " + said(a[i]) + " at position " + std::to_string(i);
  }
  return "expected " + expected + ", got '" + list.getEntry(key).getAny().typeName() + "'";
}
}  // namespace

SceneSection::SceneSection(const Teuchos::ParameterList& list, std::string file, std::string path)
    : list_(list), file_(std::move(file)), path_(std::move(path)) {}

std::string SceneSection::where(const std::string& key) const {
  return file_ + ": parameter '" + (path_.empty() ? key : path_ + "/" + key) + "'";
}

std::string SceneSection::location() const { return file_ + ": section '" + path_ + "'"; }

void SceneSection::markUsed(const std::string& key) { used_.insert(key), asked_.insert(key); }

bool SceneSection::has(const std::string& key) const {
  asked_.insert(key);
  return list_.isParameter(key);
}

bool SceneSection::isSection(const std::string& key) const { return has(key) && list_.isSublist(key); }

bool SceneSection::isWord(const std::string& key, const std::string& word) const {
  return has(key) && list_.isType<std::string>(key) && list_.get<std::string>(key) == word;
}

double SceneSection::getDouble(const std::string& key, double fallback) {
  markUsed(key);
  if (!has(key)) return fallback;
  if (list_.isType<double>(key)) return list_.get<double>(key);
  if (list_.isType<int>(key)) return list_.get<int>(key);
  throw InputError(where(key), notNumbers(list_, key, "a number"));
}

std::string SceneSection::requiredText(const std::string& key) const {
  auto plain = [](const std::string& k) {
    std::string out;
    for (char c : k)
      if (!std::isspace(static_cast<unsigned char>(c))) out += char(std::tolower(static_cast<unsigned char>(c)));
    return out;
  };
  for (auto it = list_.begin(); it != list_.end(); ++it) {
    const std::string& name = list_.name(it);
    if (name != key && plain(name) == plain(key))
      return "is required (the section has '" + name + "', which differs from it in spaces or capitals)";
  }
  return "is required";
}

double SceneSection::requireDouble(const std::string& key) {
  if (!has(key)) throw InputError(where(key), requiredText(key));
  return getDouble(key, 0.0);
}

int SceneSection::getInt(const std::string& key, int fallback) {
  markUsed(key);
  if (!has(key)) return fallback;
  if (list_.isType<int>(key)) return list_.get<int>(key);
  // A whole number too large for an int is read as another type: said as such, not as
  // "expected an integer" for 2147483648 (issue 49 probe).
  if (list_.isType<long long>(key) || list_.isType<double>(key))
    throw InputError(where(key), "expected an integer from -2147483648 to 2147483647");
  throw InputError(where(key), "expected an integer");
}

std::string SceneSection::getString(const std::string& key, const std::string& fallback) {
  markUsed(key);
  if (!has(key)) return fallback;
  if (list_.isType<std::string>(key)) return list_.get<std::string>(key);
  // YAML reads true and false as booleans; keys such as stability: auto|true|false want the word.
  if (list_.isType<bool>(key)) return list_.get<bool>(key) ? "true" : "false";
  throw InputError(where(key), "expected a string");
}

std::vector<std::string> SceneSection::getStringList(const std::string& key, const std::vector<std::string>& fallback) {
  markUsed(key);
  if (!has(key)) return fallback;
  if (isEmptyList(list_, key)) return {};
  if (list_.isType<Teuchos::Array<std::string>>(key)) {
    const auto& a = list_.get<Teuchos::Array<std::string>>(key);
    return std::vector<std::string>(a.begin(), a.end());
  }
  if (list_.isType<std::string>(key)) return {list_.get<std::string>(key)};
  throw InputError(where(key), "expected a list of names, e.g. [bore]");
}

std::vector<int> SceneSection::getIntList(const std::string& key, const std::vector<int>& fallback) {
  markUsed(key);
  if (!has(key)) return fallback;
  if (isEmptyList(list_, key)) return {};
  if (list_.isType<Teuchos::Array<int>>(key)) {
    const auto& a = list_.get<Teuchos::Array<int>>(key);
    return std::vector<int>(a.begin(), a.end());
  }
  if (list_.isType<int>(key)) return {list_.get<int>(key)};
  throw InputError(where(key), "expected a list of integers, e.g. [0, 1, 2]");
}

std::vector<double> SceneSection::getDoubleList(const std::string& key, const std::vector<double>& fallback) {
  markUsed(key);
  if (!has(key)) return fallback;
  if (isEmptyList(list_, key)) return {};
  if (list_.isType<Teuchos::Array<double>>(key)) {
    const auto& a = list_.get<Teuchos::Array<double>>(key);
    return std::vector<double>(a.begin(), a.end());
  }
  if (list_.isType<Teuchos::Array<int>>(key)) {
    const auto& a = list_.get<Teuchos::Array<int>>(key);
    return std::vector<double>(a.begin(), a.end());
  }
  if (list_.isType<double>(key)) return {list_.get<double>(key)};
  if (list_.isType<int>(key)) return {double(list_.get<int>(key))};
  throw InputError(where(key), notNumbers(list_, key, "a list of numbers (e.g. [0.0, 5000.0])"));
}

std::array<double, 3> SceneSection::getVector3(const std::string& key, const std::array<double, 3>& fallback) {
  markUsed(key);
  if (!has(key)) return fallback;
  std::vector<double> v;
  if (list_.isType<Teuchos::Array<double>>(key)) {
    const auto& a = list_.get<Teuchos::Array<double>>(key);
    v.assign(a.begin(), a.end());
  } else if (list_.isType<Teuchos::Array<int>>(key)) {
    const auto& a = list_.get<Teuchos::Array<int>>(key);
    v.assign(a.begin(), a.end());
  } else {
    throw InputError(where(key), "expected a list of 3 numbers, e.g. [0.0, 0.0, 1.0]");
  }
  if (v.size() != 3) throw InputError(where(key), "expected 3 numbers, got " + std::to_string(v.size()));
  return {v[0], v[1], v[2]};
}

SceneSection SceneSection::section(const std::string& key) {
  markUsed(key);
  const std::string path = path_.empty() ? key : path_ + "/" + key;
  if (!has(key)) return SceneSection(emptyList(), file_, path);
  if (!list_.isSublist(key)) throw InputError(where(key), "expected a section (a map of parameters)");
  return SceneSection(list_.sublist(key), file_, path);
}

std::vector<std::string> SceneSection::sectionNames() {
  std::vector<std::string> names;
  for (auto it = list_.begin(); it != list_.end(); ++it) {
    const auto& name = list_.name(it);
    if (list_.isSublist(name)) {
      names.push_back(name);
      markUsed(name);
    }
  }
  return names;
}

void SceneSection::rejectKeysOtherThan(const std::set<std::string>& known) const {
  for (auto it = list_.begin(); it != list_.end(); ++it) {
    const auto& name = list_.name(it);
    if (!known.count(name)) {
      std::string all;
      for (const auto& k : known) all += (all.empty() ? "" : ", ") + k;
      throw InputError(where(name), "unknown key (known here: " + all + ")");
    }
  }
}

std::vector<std::string> SceneSection::unreadKeys() const {
  std::vector<std::string> out;
  for (auto it = list_.begin(); it != list_.end(); ++it)
    if (!used_.count(list_.name(it))) out.push_back(list_.name(it));
  return out;
}

void SceneSection::rejectUnknownKeys() const {
  for (auto it = list_.begin(); it != list_.end(); ++it) {
    const auto& name = list_.name(it);
    if (!used_.count(name)) {
      std::string known;
      for (const auto& k : asked_) known += (known.empty() ? "" : ", ") + k;
      throw InputError(where(name), "unknown key (known here: " + known + ")");
    }
  }
}

}  // namespace cyclone::scenes
