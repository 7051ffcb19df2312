#include "script/script.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>
#include <string_view>

#include "io/input_file.h"
#include "scene/value_checks.h"
#include "script/api.h"
#include "script/parameters.h"
#include "script/sandbox.h"
#include "script/standard_library.h"

namespace csgray::detail {

namespace {

// A number of a -D value: a whole one as a Lua integer, as the literal
// written in the script would be (-D size=20 makes "20 mm" of
// size .. " mm", not "20.0 mm"); past 2⁵³, where doubles skip integers, a
// float.
void pushDefineNumber(lua_State* L, double number) {
  if (number == std::floor(number) && std::abs(number) <= 0x1p53)
    lua_pushinteger(L, lua_Integer(number));
  else
    lua_pushnumber(L, number);
}

// A -D value as a global.
void pushDefine(lua_State* L, const ParameterValue& value) {
  switch (value.kind) {
    case ParameterKind::Number:
      pushDefineNumber(L, value.number);
      return;
    case ParameterKind::Boolean:
      lua_pushboolean(L, value.boolean);
      return;
    case ParameterKind::String:
      lua_pushlstring(L, value.text.data(), value.text.size());
      return;
    case ParameterKind::Vector:
      lua_createtable(L, int(value.vector.size()), 0);
      for (std::size_t i = 0; i < value.vector.size(); ++i) {
        pushDefineNumber(L, value.vector[i]);
        lua_rawseti(L, -2, lua_Integer(i + 1));
      }
      return;
  }
}

constexpr std::size_t kMaxScriptBytes = std::size_t{16} << 20;

// A Lua name that is not a keyword.
bool isIdentifier(const std::string& name) {
  static const std::set<std::string> keywords = {
      "and",      "break",  "do",   "else", "elseif", "end",  "false", "for",
      "function", "goto",   "if",   "in",   "local",  "nil",  "not",   "or",
      "repeat",   "return", "then", "true", "until",  "while"};
  if (keywords.count(name)) return false;
  if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0]))) return false;
  for (char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}

}  // namespace

namespace {

// The names a script's text holds (its identifiers, keywords too; words in
// strings and comments count as well), for telling a -D that no line
// reads.
std::set<std::string, std::less<>> namesIn(std::string_view source) {
  std::set<std::string, std::less<>> names;
  auto starts = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; };
  auto goes = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (std::size_t i = 0; i < source.size();) {
    if (starts(source[i])) {
      std::size_t end = i;
      while (end < source.size() && goes(source[end])) ++end;
      names.emplace(source.substr(i, end - i));
      i = end;
    } else if (std::isdigit(static_cast<unsigned char>(source[i]))) {
      while (i < source.size() && goes(source[i])) ++i;  // 1e5, 0x1F: a number
    } else {
      ++i;
    }
  }
  return names;
}

// A -D whose name the script never writes sets a global nothing reads: a
// typo (-D Width=50 for width) would change nothing, silently.
void warnOfUnreadDefines(std::string_view source, const ScriptOptions& options,
                         const std::string& chunkName) {
  if (!options.warn || options.defines.empty()) return;
  const auto names = namesIn(source);
  for (const auto& [name, text] : options.defines) {
    if (names.contains(name)) continue;
    std::string nearest;
    std::size_t best = 3;
    for (const std::string& n : names)
      if (const std::size_t d = editDistance(name, n); d < best) best = d, nearest = n;
    options.warn("-D " + shownValue(name) + ": " + chunkName + " never names " + shownValue(name) +
                 (nearest.empty() ? "" : "; did you mean " + nearest + "?"));
  }
}

}  // namespace

Scene runScript(const std::string& source, const std::string& chunkName,
                const ScriptOptions& options) {
  Sandbox sandbox(options.limits);
  sandbox.print = options.print;
  lua_State* L = sandbox.state();
  registerScriptApi(L, options);
  loadStandardLibrary(L);
  // Annotated globals (script/parameters.h): a -D is checked against its
  // annotation, and replaces the default of a plain `name = value`.
  const std::vector<Parameter> parameters = findParameters(source, chunkName);
  std::vector<std::string> defined;
  for (const auto& [name, text] : options.defines) {
    const std::string shown = shownValue(name);
    if (!isIdentifier(name))
      throw DefineError("-D " + shown + "=...: '" + shown + "' is not a valid Lua name");
    if (std::find(defined.begin(), defined.end(), name) != defined.end())
      throw DefineError("-D " + shown + "=...: '" + shown + "' is given twice");
    bool builtIn = lua_getglobal(L, name.c_str()) != LUA_TNIL;
    lua_pop(L, 1);
    if (builtIn) throw DefineError("-D " + shown + "=...: '" + shown + "' is a built-in name");
    auto parameter = std::find_if(parameters.begin(), parameters.end(),
                                  [&](const Parameter& p) { return p.name == name; });
    pushDefine(L, parameter == parameters.end()
                      ? plainDefineValue(name, text)
                      : parameterDefineValue(*parameter, text, chunkName));
    lua_setglobal(L, name.c_str());
    defined.push_back(name);
  }
  warnOfUnreadDefines(source, options, chunkName);
  int results = sandbox.run(withDefinedDefaults(source, parameters, defined), chunkName);
  if (results == 0)
    throw ScriptError(chunkName +
                      ": the script returned nothing; end it with 'return <solid>' or "
                      "'return scene{...}'");
  try {
    return sceneFromValue(L, -results);
  } catch (const std::invalid_argument& e) {
    throw ScriptError(chunkName + ": " + e.what());
  }
}

namespace {

// The text of a script file, without a byte-order mark and with a first
// "#!" line kept empty. Throws ScriptError.
std::string readScriptText(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
    throw ScriptError(path + ": is a folder, not a script");
  // A device is read too, up to the limit (/dev/zero is too large); a FIFO
  // or a socket is refused, since reading one may wait for ever.
  InputFile file(path, /*devicesToo=*/true);
  if (!file.problem().empty()) throw ScriptError(path + ": cannot open script: " + file.problem());
  // At most kMaxScriptBytes + 1 bytes: a script is usually a few kilobytes.
  std::string text;
  if (!file.readUpTo(text, kMaxScriptBytes + 1))
    throw ScriptError(path + ": cannot read script: " + file.problem());
  if (text.size() > kMaxScriptBytes)
    throw ScriptError(path + ": script is larger than " + std::to_string(kMaxScriptBytes >> 20) +
                      " MiB");
  // A UTF-8 byte-order mark, and a first line "#!..." (as lua itself allows);
  // the line is kept empty so that line numbers stay right.
  if (text.starts_with("\xEF\xBB\xBF")) text.erase(0, 3);
  if (text.starts_with("#"))
    text.erase(0, text.find('\n') == std::string::npos ? text.size() : text.find('\n'));
  return text;
}

}  // namespace

Scene runScriptFile(const std::string& path, const ScriptOptions& options) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  // OpenSCAD's source would run as Lua, and fail on its first line.
  if (extension == ".scad")
    throw ScriptError(path +
                      ": csgray reads OpenSCAD's .csg files, not its .scad source: export one "
                      "with openscad -o part.csg " +
                      std::filesystem::path(path).filename().string() +
                      " and give csgray the .csg file");
  if (extension == ".csg") {
    ScriptOptions withFolder = options;
    withFolder.folder = std::filesystem::path(path).parent_path().string();
    if (withFolder.folder.empty()) withFolder.folder = ".";
    return csgFileScene(path, withFolder);
  }
  const std::string text = readScriptText(path);
  ScriptOptions withFolder = options;
  withFolder.folder = std::filesystem::path(path).parent_path().string();
  if (withFolder.folder.empty()) withFolder.folder = ".";
  return runScript(text, path, withFolder);
}

std::vector<Parameter> scriptFileParameters(const std::string& path) {
  return findParameters(readScriptText(path), path);
}

}  // namespace csgray::detail
