// OpenSCAD's .csg files: the tree that OpenSCAD writes with `openscad -o
// part.csg`, a statement per node, `name(arguments);` or `name(arguments)
// { children }`, with an optional modifier character in front (% # ! *).
// Arguments are numbers, booleans, strings, undef and vectors of them,
// positional or named (`r = 5`, `$fn = 0`). This reads the text into
// nodes; csg_import.h makes them solids and regions.
#pragma once

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace csgray::detail {

struct CsgValue {
  enum class Kind { Undef, Number, Boolean, String, Vector };
  Kind kind = Kind::Undef;
  double number = 0.0;
  bool boolean = false;
  std::string text;
  std::vector<CsgValue> items;
};

struct CsgNode {
  std::string name;
  char modifier = 0;  // '%', '#', '!', '*' or 0
  int line = 0;
  std::vector<CsgValue> positional;
  std::map<std::string, CsgValue> named;
  std::vector<CsgNode> children;
};

// A fault of the file: its message is "file:line: what".
class CsgError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The top-level statements of text; fileName is used in messages. Throws
// CsgError at the first thing that is not the format (an unclosed brace, a
// stray character, a number that does not parse, nesting deeper than 1000).
std::vector<CsgNode> parseCsg(const std::string& text, const std::string& fileName);

// The subtree of node as text, without the lines it stands on: two nodes
// have the same key exactly when they and their children are written
// alike (numbers to the last bit), so they make the same shape.
std::string csgNodeKey(const CsgNode& node);

}  // namespace csgray::detail
