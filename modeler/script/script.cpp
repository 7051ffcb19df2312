#include "modeler/script/script.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "modeler/script/api.h"
#include "modeler/script/sandbox.h"

namespace csgray {

namespace {

// -D values: numbers, true/false, or strings with optional quotes.
void pushDefine(lua_State* L, const std::string& value) {
  if (value == "true" || value == "false") {
    lua_pushboolean(L, value == "true");
    return;
  }
  if (!value.empty()) {
    char* end = nullptr;
    errno = 0;
    double number = std::strtod(value.c_str(), &end);
    if (*end == '\0' && errno == 0) {
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

bool isIdentifier(const std::string& name) {
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
  registerScriptApi(L);
  for (const auto& [name, value] : options.defines) {
    if (!isIdentifier(name))
      throw ScriptError("-D " + name + "=...: '" + name + "' is not a valid Lua name");
    pushDefine(L, value);
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
  std::ifstream file(path, std::ios::binary);
  if (!file) throw ScriptError(path + ": cannot open script: " + std::strerror(errno));
  std::ostringstream text;
  text << file.rdbuf();
  if (file.bad()) throw ScriptError(path + ": cannot read script");
  return runScript(text.str(), path, options);
}

}  // namespace csgray
