#pragma once
// Strict reading of a scene (Teuchos YAML parameter list): every value is
// checked for type and range, and a key the code does not know is an error
// naming the file and the full key path, so a typo never silently falls back
// to a default.
#include <Teuchos_ParameterList.hpp>

#include <array>
#include <functional>
#include <initializer_list>
#include <set>
#include <string>
#include <vector>

#include "cyclone/core/Error.hpp"

namespace cyclone::scenes {

/// The scene's YAML as a parameter list; InputError naming `source` when it is not valid
/// YAML. An empty list (`write: []`), which Teuchos cannot type, reads as an empty list
/// through SceneSection's list getters.
Teuchos::RCP<Teuchos::ParameterList> parseSceneYaml(const std::string& yaml, const std::string& source);

class SceneSection {
public:
  SceneSection(const Teuchos::ParameterList& list, std::string file, std::string path);

  bool has(const std::string& key) const;
  /// Whether the key holds a section (a map) rather than a value.
  bool isSection(const std::string& key) const;
  /// The key holds the string `word` (e.g. harmonics: auto).
  bool isWord(const std::string& key, const std::string& word) const;
  double getDouble(const std::string& key, double fallback);
  double requireDouble(const std::string& key);
  int getInt(const std::string& key, int fallback);
  std::string getString(const std::string& key, const std::string& fallback);
  std::vector<std::string> getStringList(const std::string& key, const std::vector<std::string>& fallback);
  std::vector<int> getIntList(const std::string& key, const std::vector<int>& fallback);
  std::vector<double> getDoubleList(const std::string& key, const std::vector<double>& fallback);
  std::array<double, 3> getVector3(const std::string& key, const std::array<double, 3>& fallback);
  SceneSection section(const std::string& key);  ///< empty section if absent
  std::vector<std::string> sectionNames();       ///< names of all sublists (marks them used)

  /// Throws InputError for any key that was never asked for.
  void rejectUnknownKeys() const;
  /// The keys present that were never asked for (for a warning where they may stay).
  std::vector<std::string> unreadKeys() const;
  /// Throws InputError for any key not in `known` (before the keys are read).
  void rejectKeysOtherThan(const std::set<std::string>& known) const;
  /// "file: parameter 'path/key'" for messages.
  std::string where(const std::string& key) const;
  /// "is required" for a missing key, naming a key of the section that differs from it
  /// only in spaces or capitals ('engine_order ' quoted with a trailing space was met by
  /// "engine_order is required" alone).
  std::string requiredText(const std::string& key) const;
  /// "file: section 'path'" for messages about the section as a whole.
  std::string location() const;
  /// A key naming one of `choices` (its word and what it means; `fallback` when the key is
  /// absent): what the word means. Any other word is an InputError under the key saying
  /// refusal(word), the choices and what each means.
  template <class T>
  T getChoice(const std::string& key, const std::string& fallback,
              std::initializer_list<std::pair<const char*, T>> choices,
              const std::function<std::string(const std::string& word)>& refusal) {
    const std::string word = getString(key, fallback);
    for (const auto& [name, meaning] : choices)
      if (word == name) return meaning;
    throw InputError(where(key), refusal(word));
  }
  /// Runs `read` (a library call that checks a value read from `key`) and puts its
  /// InputError under that key: the library names no scene key, the reader does.
  template <class Read>
  auto underKey(const std::string& key, Read&& read) const -> decltype(read()) {
    try {
      return read();
    } catch (const InputError& e) {
      throw InputError(where(key), e.problem());
    }
  }

private:
  const Teuchos::ParameterList& list_;
  std::string file_, path_;
  std::set<std::string> used_;
  // Every key asked about (has() included): what an unknown key's message lists as known
  // here, so that keys this scene leaves out (gap, peak_stress) are named too.
  mutable std::set<std::string> asked_;
  void markUsed(const std::string& key);
};

}  // namespace cyclone::scenes
