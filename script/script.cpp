#include "script/script.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <sstream>

#include "io/input_file.h"
#include "scene/value_checks.h"
#include "script/api.h"
#include "script/sandbox.h"

namespace csgray::detail {

namespace {

// -D values: numbers, true/false, or strings with optional quotes.
void pushDefine(lua_State* L, const std::string& name, const std::string& value) {
  if (value == "true" || value == "false") {
    lua_pushboolean(L, value == "true");
    return;
  }
  if (!value.empty()) {
    char* end = nullptr;
    errno = 0;
    double number = std::strtod(value.c_str(), &end);
    if (*end == '\0') {
      // strtod's ERANGE is also set for a denormal such as 4.9e-324, which
      // is finite and taken; "inf" and "nan" are written so; digits that
      // overflow are too large, and those that underflow to 0 too small.
      const std::string refused = "-D " + shownValue(name) + "=" + shownValue(value) + ": ";
      if (!std::isfinite(number))
        throw DefineError(refused +
                          (value.find_first_of("iInN") != std::string::npos
                               ? "not a finite number"
                               : "out of range (numbers reach 1.8e308 either side of 0)"));
      if (errno == ERANGE && number == 0.0)
        throw DefineError(refused + "too close to 0 (the least number above 0 is 4.9e-324)");
      lua_pushnumber(L, number);
      return;
    }
  }
  std::string text = value;
  if (text.size() >= 2 && (text.front() == '"' || text.front() == '\'') &&
      text.back() == text.front())
    text = text.substr(1, text.size() - 2);
  lua_pushlstring(L, text.data(), text.size());
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

Scene runScript(const std::string& source, const std::string& chunkName,
                const ScriptOptions& options) {
  Sandbox sandbox(options.limits);
  lua_State* L = sandbox.state();
  registerScriptApi(L, options);
  for (const auto& [name, value] : options.defines) {
    const std::string shown = shownValue(name);
    if (!isIdentifier(name))
      throw DefineError("-D " + shown + "=...: '" + shown + "' is not a valid Lua name");
    bool builtIn = lua_getglobal(L, name.c_str()) != LUA_TNIL;
    lua_pop(L, 1);
    if (builtIn) throw DefineError("-D " + shown + "=...: '" + shown + "' is a built-in name");
    pushDefine(L, name, value);
    lua_setglobal(L, name.c_str());
  }
  int results = sandbox.run(source, chunkName);
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

Scene runScriptFile(const std::string& path, const ScriptOptions& options) {
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
  ScriptOptions withFolder = options;
  withFolder.folder = std::filesystem::path(path).parent_path().string();
  if (withFolder.folder.empty()) withFolder.folder = ".";
  return runScript(text, path, withFolder);
}

}  // namespace csgray::detail
