#include "view/view_state_json.h"

#include "view/json_text.h"

namespace csgray::detail {

namespace {

std::string valueJson(const ParameterValue& value) {
  switch (value.kind) {
    case ParameterKind::Number:
      return jsonNumber(value.number);
    case ParameterKind::Boolean:
      return value.boolean ? "true" : "false";
    case ParameterKind::String:
      return jsonString(value.text);
    case ParameterKind::Vector: {
      std::string out = "[";
      for (std::size_t i = 0; i < value.vector.size(); ++i)
        out += (i ? "," : "") + jsonNumber(value.vector[i]);
      return out + "]";
    }
  }
  return "null";
}

const char* kindText(ParameterKind kind) {
  switch (kind) {
    case ParameterKind::Number:
      return "number";
    case ParameterKind::Boolean:
      return "boolean";
    case ParameterKind::String:
      return "string";
    case ParameterKind::Vector:
      return "vector";
  }
  return "";
}

std::string parameterJson(const Parameter& p, const SessionState& state,
                          const std::string& script) {
  ParameterValue value = p.defaultValue;
  for (const auto& [name, text] : state.defines)
    if (name == p.name) try {
        value = parameterDefineValue(p, text, script);
      } catch (const std::exception&) {
        // A value the script's new annotation refuses: the error says so.
      }
  std::string out = "{\"name\":" + jsonString(p.name) + ",\"line\":" + std::to_string(p.line) +
                    ",\"kind\":\"" + kindText(p.kind) + "\",\"value\":" + valueJson(value) +
                    ",\"default\":" + valueJson(p.defaultValue);
  if (p.hasRange)
    out += ",\"min\":" + jsonNumber(p.min) + ",\"max\":" + jsonNumber(p.max) +
           ",\"step\":" + jsonNumber(p.step);
  if (!p.choices.empty()) {
    out += ",\"choices\":[";
    for (std::size_t i = 0; i < p.choices.size(); ++i)
      out += (i ? "," : "") + valueJson(p.choices[i]);
    out += "]";
  }
  return out + ",\"description\":" + jsonString(p.description) + "}";
}

}  // namespace

std::string stateJson(const SessionState& state, const std::string& script) {
  std::string out = "{\"version\":" + std::to_string(state.version) +
                    ",\"script\":" + jsonString(script) + ",\"error\":" + jsonString(state.error);
  if (state.scene) {
    const Bounds& b = state.bounds;  // the model's: no ghosts, no surfaces
    out += ",\"bounds\":";
    out += b.empty() || !b.finite()
               ? "null"
               : "{\"lo\":" + jsonVector(b.lo) + ",\"hi\":" + jsonVector(b.hi) + "}";
    out += ",\"volume\":" + jsonNumber(state.volume);
    out += ",\"ghosts\":" + std::to_string(state.scene->ghosts.size()) +
           ",\"highlights\":" + std::to_string(state.scene->highlights.size());
    if (const auto& c = state.scene->camera)
      out += ",\"camera\":{\"eye\":" + jsonVector(c->eye) + ",\"lookAt\":" + jsonVector(c->lookAt) +
             ",\"up\":" + jsonVector(c->up) + ",\"fov\":" + jsonNumber(c->fovDegrees) +
             ",\"ortho\":" + (c->orthographic ? "true" : "false") +
             ",\"orthoWidth\":" + jsonNumber(c->orthoWidth) + "}";
    else
      out += ",\"camera\":null";
  } else {
    out += ",\"bounds\":null,\"volume\":null,\"ghosts\":0,\"highlights\":0,\"camera\":null";
  }
  out += ",\"parameters\":[";
  for (std::size_t i = 0; i < state.parameters.size(); ++i)
    out += (i ? "," : "") + parameterJson(state.parameters[i], state, script);
  out += "],\"files\":[";
  for (std::size_t i = 0; i < state.files.size(); ++i)
    out += (i ? "," : "") + jsonString(state.files[i]);
  return out + "]}";
}

}  // namespace csgray::detail
