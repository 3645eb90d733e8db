// A scene's YAML text read into Teuchos' parameter lists: its size and nesting checked
// first, what Teuchos' reader does not take made plain, the reader's failure said.
#include <Teuchos_YamlParameterListCoreHelpers.hpp>

#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cyclone/core/Error.hpp"
#include "cyclone/scenes/SceneSection.hpp"
#include "SceneYaml.hpp"

namespace cyclone::scenes {

namespace {
// Limits checked before Teuchos reads the text: its parser's time grows much faster than
// the text with nesting and long lists (issue 20: 10 000 nested maps, 50 kB, over 60 s;
// a 10 MB list over 100 s). Shipped scenes are about 2 kB, nested 5 deep; matrices and
// meshes live in files.
constexpr std::size_t kMaxSceneBytes = 1 << 20;
constexpr int kMaxNesting = 32;

void checkSceneLimits(const std::string& yaml, const std::string& source) {
  if (yaml.size() > kMaxSceneBytes)
    throw InputError(source, "the scene is " + std::to_string(yaml.size() / 1024) +
                                 " kB; scenes are limited to 1 MB (put meshes and matrices in files)");
  int depth = 0, line = 1;
  bool quoted = false, comment = false, lineStart = true;
  char quote = 0;
  int indent = 0;
  auto tooDeep = [&] {
    throw InputError(source + ": line " + std::to_string(line),
                     "nested more than " + std::to_string(kMaxNesting) + " levels deep (a scene needs about 5); not read");
  };
  for (const char c : yaml) {
    if (c == '\n') {  // a quote left open ends with its line here (scenes have no multi-line strings)
      ++line, comment = quoted = false, lineStart = true, indent = 0;
      continue;
    }
    if (lineStart) {
      if (c == ' ') {
        ++indent;
        continue;
      }
      lineStart = false;
      if (indent > 2 * kMaxNesting) tooDeep();  // block nesting: two spaces a level in practice
    }
    if (comment) continue;
    if (quoted) {
      if (c == quote) quoted = false;
      continue;
    }
    if (c == '#') comment = true;
    else if (c == '"' || c == '\'') quoted = true, quote = c;
    else if ((c == '{' || c == '[') && ++depth > kMaxNesting) tooDeep();
    else if (c == '}' || c == ']') --depth;
  }
}

// What Teuchos' YAML reader does not take, made plain before it reads the text (issue 49:
// each gave a parser state number): a UTF-8 byte-order mark (an editor's, valid YAML) is
// dropped; a block list whose dashes stand at its key's own indentation (valid YAML, a
// common style) is indented under its key; anchors and aliases (&name, *name) are refused
// naming the line. A key's `[]` becomes kEmptyList.
constexpr std::size_t kLongestPlainLine = 2000;

std::string plainSceneText(const std::string& yaml, const std::string& source) {
  // A key's empty list at the line's end or inside a flow mapping ({preload: []} was
  // "Parser failure at line 80 column 27"; issue 49's sixth probe).
  static const std::regex emptyList(R"((:[ \t]*)\[[ \t]*\](?=[ \t]*([,}]|#|$)))");
  static const std::regex valuelessKey(R"(^[^#\s-][^:#]*:[ \t]*(#.*)?$)");
  static const std::regex anchorOrAlias(R"((^|[:\[,{-])[ \t]*[&*][A-Za-z0-9_.-]+)");
  const bool bom = yaml.rfind("\xEF\xBB\xBF", 0) == 0;
  std::istringstream in(bom ? yaml.substr(3) : yaml);
  std::ostringstream text;
  std::string line;
  int number = 0, keyIndent = -1, listIndent = -1;
  bool anything = false;
  // The block mappings' keys seen so far, per indentation of the mappings open at this
  // line (a key given twice: the YAML parser said only "Parser failure at line 15").
  static const std::regex blockKey(R"(^(- )?([A-Za-z_][A-Za-z0-9_.-]*)[ \t]*:([ \t]|$))");
  std::vector<std::pair<int, std::map<std::string, int>>> open;
  while (std::getline(in, line)) {
    ++number;
    // std::regex matches recursively, a frame per character: a 30 000-character key
    // overflowed the stack (SIGSEGV; issue 49 probe). A line that long is data (a matrix's
    // values): passed to the YAML reader as it is.
    if (line.size() > kLongestPlainLine) {
      anything = true;
      text << line << "\n";
      continue;
    }
    const auto first = line.find_first_not_of(' ');
    const bool blank = first == std::string::npos || line[first] == '#';
    const int indent = blank ? -1 : int(first);
    const std::string content = blank ? std::string() : line.substr(first);
    if (!blank && !anything) {
      anything = true;
      if (content.rfind("- ", 0) == 0 || content == "-")
        throw InputError(source + ": line " + std::to_string(number),
                         "the scene is a list; it must be a mapping: `cyclone:` and its sections under it");
      // `cyclone: 5` or `cyclone: [1, 2]`: the reader said only its source file's line.
      static const std::regex scalarTop(R"(^cyclone[ \t]*:[ \t]*[^ \t#{].*$)");
      if (std::regex_match(content, scalarTop))
        throw InputError(source + ": line " + std::to_string(number),
                         "`cyclone:` must hold the scene's sections, indented under it (a mapping), not a value");
    }
    if (!blank) {
      std::smatch key;
      if (std::regex_search(content, key, blockKey)) {
        // The reader keeps the first top-level key's map: any key beside 'cyclone' was
        // ignored without a word (issue 49's fourth probe).
        if (indent == 0 && !key[1].matched && key[2].str() != "cyclone")
          throw InputError(source + ": line " + std::to_string(number),
                           "only 'cyclone' is read at the top level; '" + key[2].str() +
                               "' beside it would be ignored (indent it under cyclone, or remove it)");
        // A list item's key opens a mapping two columns in; the mappings deeper than
        // this key's are closed, and so is its own where a list item starts it.
        const int at = indent + (key[1].matched ? 2 : 0);
        while (!open.empty() && (open.back().first > at || (key[1].matched && open.back().first == at))) open.pop_back();
        if (open.empty() || open.back().first < at) open.push_back({at, {}});
        auto& keys = open.back().second;
        const auto [it, fresh] = keys.emplace(key[2].str(), number);
        if (!fresh)
          throw InputError(source + ": line " + std::to_string(number),
                           "the key '" + key[2].str() + "' is given twice in the same section (first at line " +
                               std::to_string(it->second) + ")");
      } else {
        while (!open.empty() && open.back().first > indent) open.pop_back();
      }
    }
    if (!blank) {
      std::string code = content;  // without a trailing comment or quoted text
      for (std::size_t i = 0; i < code.size(); ++i)
        if (code[i] == '"' || code[i] == '\'') {
          const auto end = code.find(code[i], i + 1);
          code.erase(i, end == std::string::npos ? std::string::npos : end - i + 1);
          --i;
        } else if (code[i] == '#') {
          code.erase(i);
          break;
        }
      if (std::regex_search(code, anchorOrAlias))
        throw InputError(source + ": line " + std::to_string(number),
                         "YAML anchors and aliases (&name, *name) are not read by the scene reader: write the "
                         "value out where it is used");
      const bool dash = content.rfind("- ", 0) == 0 || content == "-";
      if (listIndent >= 0 && (indent < listIndent || (indent == listIndent && !dash))) listIndent = -1;
      if (listIndent < 0 && dash && indent == keyIndent) listIndent = indent;
      keyIndent = std::regex_search(content, valuelessKey) ? indent : -1;
    }
    if (listIndent >= 0 && !blank) line.insert(0, "  ");
    text << std::regex_replace(line, emptyList, std::string("$1") + kEmptyList) << "\n";
  }
  if (!anything)
    throw InputError(source, "the scene is empty (nothing but blank lines and comments): it needs `cyclone:` and its "
                             "sections, e.g. `cyclone print-demo-scene`");
  return text.str();
}

}  // namespace

Teuchos::RCP<Teuchos::ParameterList> parseSceneYaml(const std::string& yaml, const std::string& source) {
  checkSceneLimits(yaml, source);
  const std::string text = plainSceneText(yaml, source);
  Teuchos::RCP<Teuchos::ParameterList> root;
  try {
    root = Teuchos::getParametersFromYamlString(text);
  } catch (const std::exception& e) {
    // The reader's first lines say where; the rest is its parser's state.
    std::istringstream what(e.what());
    std::string line, shown;
    for (int i = 0; i < 4 && std::getline(what, line); ++i) shown += (i ? "\n" : "") + line;
    throw InputError(source, "not a valid YAML scene (two-space indentation and flow lists [a, b] are safest): " +
                                 shown);
  }
  return root;
}

}  // namespace cyclone::scenes
