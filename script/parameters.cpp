#include "script/parameters.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <optional>

#include "scene/value_checks.h"
#include "script/script.h"

namespace csgray::detail {

namespace {

std::string numberText(double value) {
  char text[32];
  auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front())))
    text.remove_prefix(1);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
    text.remove_suffix(1);
  return text;
}

// The whole of text as a finite number, or nothing.
std::optional<double> wholeNumber(std::string_view text) {
  text = trimmed(text);
  if (text.empty()) return std::nullopt;
  const std::string copy(text);
  char* end = nullptr;
  const double value = std::strtod(copy.c_str(), &end);
  if (*end != '\0' || !std::isfinite(value)) return std::nullopt;
  return value;
}

// Numbers separated by commas: "90, 60, 30". Nothing if any is not one.
std::optional<std::vector<double>> numberList(std::string_view text) {
  std::vector<double> numbers;
  while (true) {
    const std::size_t comma = text.find(',');
    std::optional<double> number = wholeNumber(text.substr(0, comma));
    if (!number) return std::nullopt;
    numbers.push_back(*number);
    if (comma == std::string_view::npos) return numbers;
    text.remove_prefix(comma + 1);
  }
}

// Reads a script line from the left; every read skips the spaces before it.
class LineReader {
 public:
  explicit LineReader(std::string_view line) : line_(line) {}

  std::size_t position() const { return at_; }
  std::string_view rest() const { return line_.substr(at_); }
  void skipSpaces() {
    while (at_ < line_.size() && (line_[at_] == ' ' || line_[at_] == '\t')) ++at_;
  }
  bool take(std::string_view word) {
    skipSpaces();
    if (line_.substr(at_, word.size()) != word) return false;
    at_ += word.size();
    return true;
  }
  // A Lua name (keywords are left to the caller).
  std::string name() {
    skipSpaces();
    std::size_t end = at_;
    while (end < line_.size() &&
           (std::isalnum(static_cast<unsigned char>(line_[end])) || line_[end] == '_'))
      ++end;
    if (end == at_ || std::isdigit(static_cast<unsigned char>(line_[at_]))) return {};
    std::string word(line_.substr(at_, end - at_));
    at_ = end;
    return word;
  }
  // A literal: a number, a string in quotes without escapes, true, false,
  // or {numbers}.
  std::optional<ParameterValue> literal() {
    skipSpaces();
    if (at_ >= line_.size()) return std::nullopt;
    ParameterValue value;
    const char c = line_[at_];
    if (c == '"' || c == '\'') {
      const std::size_t close = line_.find(c, at_ + 1);
      if (close == std::string_view::npos) return std::nullopt;
      value.kind = ParameterKind::String;
      value.text = std::string(line_.substr(at_ + 1, close - at_ - 1));
      if (value.text.find('\\') != std::string::npos) return std::nullopt;
      at_ = close + 1;
      return value;
    }
    if (c == '{') {
      const std::size_t close = line_.find('}', at_);
      if (close == std::string_view::npos) return std::nullopt;
      auto numbers = numberList(line_.substr(at_ + 1, close - at_ - 1));
      if (!numbers) return std::nullopt;
      value.kind = ParameterKind::Vector;
      value.vector = *numbers;
      at_ = close + 1;
      return value;
    }
    const std::size_t start = at_;
    const std::string word = name();
    if (word == "true" || word == "false") {
      value.kind = ParameterKind::Boolean;
      value.boolean = word == "true";
      return value;
    }
    at_ = start;
    if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-')) return std::nullopt;
    std::size_t end = at_ + 1;
    // Digits, a point and an exponent; "--" starts the comment.
    while (end < line_.size() &&
           (std::isalnum(static_cast<unsigned char>(line_[end])) || line_[end] == '.' ||
            ((line_[end] == '-' || line_[end] == '+') && (line_[end - 1] | 0x20) == 'e')))
      ++end;
    std::optional<double> number = wholeNumber(line_.substr(at_, end - at_));
    if (!number) return std::nullopt;
    value.number = *number;
    at_ = end;
    return value;
  }

 private:
  std::string_view line_;
  std::size_t at_ = 0;
};

const char* kindName(ParameterKind kind) {
  switch (kind) {
    case ParameterKind::Number:
      return "a number";
    case ParameterKind::Boolean:
      return "true or false";
    case ParameterKind::String:
      return "a string";
    case ParameterKind::Vector:
      return "a vector";
  }
  return "";
}

std::string shown(const ParameterValue& value) {
  return value.kind == ParameterKind::String ? "\"" + value.text + "\"" : value.defineText();
}

// Fills the parameter's range or choices from the text between the
// brackets; the error (without the line) when it does not fit.
std::string readSpec(std::string_view spec, Parameter& p) {
  spec = trimmed(spec);
  if (spec.empty()) return {};
  if (p.kind == ParameterKind::Boolean)
    return "a boolean takes empty brackets [] (a check box), not [" + std::string(spec) + "]";
  if (spec.find(':') != std::string_view::npos) {
    if (p.kind != ParameterKind::Number && p.kind != ParameterKind::Vector)
      return "a range [min:max] needs a number or a vector of numbers";
    std::vector<double> bounds;
    std::string_view rest = spec;
    while (true) {
      const std::size_t colon = rest.find(':');
      std::optional<double> number = wholeNumber(rest.substr(0, colon));
      if (!number) return "[" + std::string(spec) + "] is not [min:max] or [min:step:max]";
      bounds.push_back(*number);
      if (colon == std::string_view::npos) break;
      rest.remove_prefix(colon + 1);
    }
    if (bounds.size() < 2 || bounds.size() > 3)
      return "[" + std::string(spec) + "] is not [min:max] or [min:step:max]";
    p.hasRange = true;
    p.min = bounds.front();
    p.max = bounds.back();
    p.step = bounds.size() == 3 ? bounds[1] : 0.0;
    if (p.min > p.max)
      return "[" + std::string(spec) + "]: min is above max (the order is min:step:max)";
    if (bounds.size() == 3 && !(p.step > 0.0))
      return "[" + std::string(spec) + "]: the step must be above 0";
    const std::vector<double> values = p.kind == ParameterKind::Vector
                                           ? p.defaultValue.vector
                                           : std::vector<double>{p.defaultValue.number};
    for (double v : values)
      if (v < p.min || v > p.max)
        return "the default " + shown(p.defaultValue) + " is outside [" + std::string(spec) + "]";
    return {};
  }
  if (p.kind != ParameterKind::Number && p.kind != ParameterKind::String)
    return "choices [a, b] need a number or a string";
  std::string_view rest = spec;
  while (true) {
    const std::size_t comma = rest.find(',');
    LineReader reader(rest.substr(0, comma));
    std::optional<ParameterValue> choice = reader.literal();
    reader.skipSpaces();
    if (!choice || !reader.rest().empty() || choice->kind != p.kind)
      return "[" + std::string(spec) + "]: each choice must be " + kindName(p.kind) +
             " like the default";
    p.choices.push_back(*choice);
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
  if (std::find(p.choices.begin(), p.choices.end(), p.defaultValue) == p.choices.end())
    return "the default " + shown(p.defaultValue) + " is not among [" + std::string(spec) + "]";
  return {};
}

// The parameter a line declares, if it does; throws ScriptError for an
// annotation that does not fit.
std::optional<Parameter> lineParameter(std::string_view line, std::size_t lineStart, int number,
                                       const std::string& chunkName) {
  LineReader reader(line);
  if (line.empty() || line[0] == ' ' || line[0] == '\t') return std::nullopt;
  Parameter p;
  p.line = number;
  const bool local = reader.take("local ") || reader.take("local\t");
  p.name = reader.name();
  if (p.name.empty() || p.name == "local" || !reader.take("=")) return std::nullopt;
  // `name or value`, or a literal.
  if (LineReader lookahead = reader; lookahead.name() == p.name && lookahead.take("or ")) {
    reader = lookahead;
    p.readsGlobal = true;
  }
  if (local && !p.readsGlobal) return std::nullopt;  // a local that -D could not set
  reader.skipSpaces();
  p.valueBegin = lineStart + reader.position();
  std::optional<ParameterValue> value = reader.literal();
  p.valueEnd = lineStart + reader.position();
  if (!value) {
    // An expression: still an error when its comment is an annotation.
    const std::size_t comment = line.find("--", reader.position());
    if (comment == std::string_view::npos) return std::nullopt;
    reader = LineReader(line.substr(comment));
  }
  reader.take(";");
  // "--[[" and "--[=[" open long comments; "-- [" or "--[" and a spec
  // annotate.
  if (!reader.take("--")) return std::nullopt;
  std::string_view comment = reader.rest();
  if (comment.starts_with("[[") || comment.starts_with("[=")) return std::nullopt;
  comment = trimmed(comment);
  if (!comment.starts_with("[")) return std::nullopt;
  const std::size_t close = comment.find(']');
  if (close == std::string_view::npos) return std::nullopt;
  const std::string_view spec = trimmed(comment.substr(1, close - 1));
  const bool annotation = spec.empty() || spec.find_first_of(":,") != std::string_view::npos ||
                          spec.front() == '"' || spec.front() == '\'';
  if (!annotation) return std::nullopt;  // "-- [mm] the length"
  const std::string where =
      chunkName + ":" + std::to_string(number) + ": parameter " + p.name + ": ";
  if (!value)
    throw ScriptError(where +
                      "its value must be a number, a string in quotes, true, false or "
                      "{numbers} to be a parameter");
  p.kind = value->kind;
  p.defaultValue = *value;
  if (std::string problem = readSpec(spec, p); !problem.empty()) throw ScriptError(where + problem);
  p.description = std::string(trimmed(comment.substr(close + 1)));
  return p;
}

}  // namespace

std::string ParameterValue::defineText() const {
  switch (kind) {
    case ParameterKind::Number:
      return numberText(number);
    case ParameterKind::Boolean:
      return boolean ? "true" : "false";
    case ParameterKind::String:
      return text;
    case ParameterKind::Vector: {
      std::string out = "{";
      for (std::size_t i = 0; i < vector.size(); ++i) out += (i ? "," : "") + numberText(vector[i]);
      return out + "}";
    }
  }
  return {};
}

std::vector<Parameter> findParameters(std::string_view source, const std::string& chunkName) {
  std::vector<Parameter> parameters;
  std::size_t start = 0;
  for (int number = 1; start <= source.size(); ++number) {
    std::size_t end = source.find('\n', start);
    if (end == std::string_view::npos) end = source.size();
    std::string_view line = source.substr(start, end - start);
    if (line.ends_with('\r')) line.remove_suffix(1);
    if (std::optional<Parameter> p = lineParameter(line, start, number, chunkName)) {
      for (const Parameter& q : parameters)
        if (q.name == p->name)
          throw ScriptError(chunkName + ":" + std::to_string(number) + ": parameter " + p->name +
                            " is declared on line " + std::to_string(q.line) + " already");
      parameters.push_back(std::move(*p));
    }
    start = end + 1;
  }
  return parameters;
}

ParameterValue plainDefineValue(const std::string& name, const std::string& text) {
  ParameterValue value;
  if (text == "true" || text == "false") {
    value.kind = ParameterKind::Boolean;
    value.boolean = text == "true";
    return value;
  }
  const std::string refused = "-D " + shownValue(name) + "=" + shownValue(text) + ": ";
  // A value that opens a brace is a vector, one that lacks its closing
  // brace a typo rather than a string; a string may start with a brace in
  // quotes ("{a}").
  if (!text.empty() && (text.front() == '{' || text.back() == '}')) {
    auto numbers = text.size() >= 2 && text.front() == '{' && text.back() == '}'
                       ? numberList(std::string_view(text).substr(1, text.size() - 2))
                       : std::nullopt;
    if (!numbers)
      throw DefineError(refused + "a vector is finite numbers between braces, e.g. {90,60,30}");
    value.kind = ParameterKind::Vector;
    value.vector = *numbers;
    return value;
  }
  if (!text.empty()) {
    char* end = nullptr;
    errno = 0;
    double number = std::strtod(text.c_str(), &end);
    if (*end == '\0') {
      // strtod's ERANGE is also set for a denormal such as 4.9e-324, which
      // is finite and taken; "inf" and "nan" are written so; digits that
      // overflow are too large, and those that underflow to 0 too small.
      if (!std::isfinite(number))
        throw DefineError(refused +
                          (text.find_first_of("iInN") != std::string::npos
                               ? "not a finite number"
                               : "out of range (numbers reach 1.8e308 either side of 0)"));
      if (errno == ERANGE && number == 0.0)
        throw DefineError(refused + "too close to 0 (the least number above 0 is 4.9e-324)");
      value.number = number;
      return value;
    }
  }
  value.kind = ParameterKind::String;
  value.text = text;
  if (text.size() >= 2 && (text.front() == '"' || text.front() == '\'') &&
      text.back() == text.front())
    value.text = text.substr(1, text.size() - 2);
  return value;
}

ParameterValue parameterDefineValue(const Parameter& p, const std::string& text,
                                    const std::string& chunkName) {
  const std::string refused = "-D " + shownValue(p.name) + "=" + shownValue(text) + ": ";
  const std::string where = " (" + chunkName + ":" + std::to_string(p.line) + ")";
  ParameterValue value = plainDefineValue(p.name, text);
  if (p.kind == ParameterKind::String && value.kind != ParameterKind::String) {
    value.kind = ParameterKind::String;  // "-D label=12" is the text "12"
    value.text = text;
  }
  if (value.kind != p.kind)
    throw DefineError(refused + shownValue(p.name) + " is " + kindName(p.kind) +
                      (p.kind == ParameterKind::Vector
                           ? " of " + std::to_string(p.defaultValue.vector.size()) +
                                 " numbers, e.g. " + shownValue(p.defaultValue.defineText())
                           : "") +
                      where);
  if (p.kind == ParameterKind::Vector && value.vector.size() != p.defaultValue.vector.size())
    throw DefineError(refused + shownValue(p.name) + " is a vector of " +
                      std::to_string(p.defaultValue.vector.size()) + " numbers, e.g. " +
                      shownValue(p.defaultValue.defineText()) + where);
  if (!p.choices.empty() &&
      std::find(p.choices.begin(), p.choices.end(), value) == p.choices.end()) {
    // Each choice as a value is shown, and at most a screen's worth of them.
    constexpr std::size_t kShownChoices = 12;
    std::string list;
    for (std::size_t i = 0; i < std::min(p.choices.size(), kShownChoices); ++i)
      list += (i == 0 ? "" : ", ") + shownValue(shown(p.choices[i]));
    if (p.choices.size() > kShownChoices)
      list += " and " + std::to_string(p.choices.size() - kShownChoices) + " more";
    throw DefineError(refused + shownValue(p.name) + " must be one of " + list + where);
  }
  if (p.hasRange) {
    const std::vector<double> numbers =
        p.kind == ParameterKind::Vector ? value.vector : std::vector<double>{value.number};
    for (double v : numbers)
      if (v < p.min || v > p.max)
        throw DefineError(refused + shownValue(p.name) +
                          (p.kind == ParameterKind::Vector ? "'s components" : "") +
                          " must be from " + numberText(p.min) + " to " + numberText(p.max) +
                          where);
  }
  return value;
}

std::string withDefinedDefaults(std::string_view source, const std::vector<Parameter>& parameters,
                                const std::vector<std::string>& definedNames) {
  std::string out(source);
  // From the end, so that earlier offsets stay right.
  for (auto p = parameters.rbegin(); p != parameters.rend(); ++p) {
    if (p->readsGlobal ||
        std::find(definedNames.begin(), definedNames.end(), p->name) == definedNames.end())
      continue;
    out.replace(p->valueBegin, p->valueEnd - p->valueBegin, p->name);
  }
  return out;
}

}  // namespace csgray::detail
