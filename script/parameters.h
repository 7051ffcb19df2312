// A script's parameters: the globals it declares with an annotation, a
// comment in brackets after the value (docs/view.md, "Parameters"):
//
//   width  = 40              -- [10:100] leg width, mm       a slider
//   step   = 2.5             -- [0.5:0.5:10]                 min:step:max
//   style  = "round"         -- ["round", "square"]          a drop-down
//   hollow = true            -- [] make it a shell            a check box
//   size   = {90, 60, 30}    -- [10:200] outer size           three sliders
//   local holes = holes or 2 -- [1:10]                        also a parameter
//
// The customizer of `csgray view` shows them; -D checks its values against
// them on every command, and a -D value replaces the default of a plain
// `name = value` line (as OpenSCAD's -D does), while `local name = name or
// value` reads it as before. The order min:step:max is OpenSCAD's.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace csgray::detail {

enum class ParameterKind { Number, Boolean, String, Vector };

// A parameter's value, or a -D's.
struct ParameterValue {
  ParameterKind kind = ParameterKind::Number;
  double number = 0.0;
  bool boolean = false;
  std::string text;
  std::vector<double> vector;

  // As -D takes it back: "40", "true", "round", "{90,60,30}"; numbers
  // with as many digits as they need to read back the same.
  std::string defineText() const;
  bool operator==(const ParameterValue&) const = default;
};

struct Parameter {
  std::string name;
  int line = 0;  // 1-based, in the script
  ParameterKind kind = ParameterKind::Number;
  ParameterValue defaultValue;
  // [min:max] or [min:step:max]; step 0 when not given. For a vector each
  // component has this range.
  bool hasRange = false;
  double min = 0.0, max = 0.0, step = 0.0;
  std::vector<ParameterValue> choices;  // ["a", "b"] or [1, 2, 3]
  std::string description;              // the text after the brackets
  // `local name = name or value`: the script reads a -D itself. Otherwise
  // the default is replaced by a -D's value: the bytes [valueBegin,
  // valueEnd) of the script.
  bool readsGlobal = false;
  std::size_t valueBegin = 0, valueEnd = 0;
};

// The annotated parameters of a script's text, in order. A line is one
// when it starts (no indentation) with `name = value` or `local name =
// name or value`, where value is a number, a string in quotes, true,
// false or {numbers}, and its comment starts with brackets that are empty
// or hold ':' or ','; other comments in brackets ("-- [mm]") are not
// annotations. Throws ScriptError "chunk:line: ..." for an annotation that
// does not fit its value.
std::vector<Parameter> findParameters(std::string_view source, const std::string& chunkName);

// A -D value without an annotation: true/false, a finite number,
// {numbers} (a vector), or else a string (quotes optional). Throws
// DefineError naming the -D.
ParameterValue plainDefineValue(const std::string& name, const std::string& text);
// A -D value for an annotated parameter: of its kind, among its choices,
// within its range. Throws DefineError naming the -D and the annotation's
// line ("-D width=500: width must be from 10 to 100 (part.lua:3)").
ParameterValue parameterDefineValue(const Parameter& parameter, const std::string& text,
                                    const std::string& chunkName);

// The script's text with each plain `name = value` parameter that a define
// sets reading the global instead (`name = name`), on the same lines.
std::string withDefinedDefaults(std::string_view source, const std::vector<Parameter>& parameters,
                                const std::vector<std::string>& definedNames);

}  // namespace csgray::detail
