#include "openscad/csg_parser.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace csgray::detail {

namespace {

// Deeper nesting than any real file has would run the parser's stack out.
constexpr int kMaxDepth = 1000;

class Parser {
 public:
  Parser(const std::string& text, const std::string& fileName) : text_(text), file_(fileName) {}

  std::vector<CsgNode> file() {
    std::vector<CsgNode> nodes;
    skipSpace();
    while (pos_ < text_.size()) {
      statement(nodes, 0);
      skipSpace();
    }
    return nodes;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw CsgError(file_ + ":" + std::to_string(line_) + ": " + what);
  }

  // What is at the cursor, for messages.
  std::string here() const {
    if (pos_ >= text_.size()) return "the end of the file";
    const char c = text_[pos_];
    if (std::isprint(static_cast<unsigned char>(c))) return std::string("'") + c + "'";
    return "byte " + std::to_string(static_cast<unsigned char>(c));
  }

  void skipSpace() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') {
        ++line_, ++pos_;
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        ++pos_;
      } else if (text_.compare(pos_, 2, "//") == 0) {
        while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
      } else if (text_.compare(pos_, 2, "/*") == 0) {
        const std::size_t end = text_.find("*/", pos_ + 2);
        if (end == std::string::npos) fail("a comment /* is not closed");
        for (std::size_t i = pos_; i < end; ++i) line_ += text_[i] == '\n';
        pos_ = end + 2;
      } else {
        return;
      }
    }
  }

  bool take(char c) {
    skipSpace();
    if (pos_ < text_.size() && text_[pos_] == c) return ++pos_, true;
    return false;
  }

  void expect(char c, const char* where) {
    if (!take(c)) fail(std::string("expected '") + c + "' " + where + ", found " + here());
  }

  std::string name() {
    skipSpace();
    const std::size_t begin = pos_;
    if (pos_ < text_.size() && text_[pos_] == '$') ++pos_;
    while (pos_ < text_.size() &&
           (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
      ++pos_;
    return text_.substr(begin, pos_ - begin);
  }

  void statement(std::vector<CsgNode>& siblings, int depth) {
    if (depth > kMaxDepth) fail("nodes nested deeper than " + std::to_string(kMaxDepth));
    skipSpace();
    if (take(';')) return;  // an empty statement
    CsgNode node;
    if (pos_ < text_.size() && std::string("%#!*").find(text_[pos_]) != std::string::npos)
      node.modifier = text_[pos_++];
    node.line = line_;
    node.name = name();
    if (node.name.empty() || node.name[0] == '$' ||
        std::isdigit(static_cast<unsigned char>(node.name[0])))
      fail("expected the name of a node, found " +
           (node.name.empty() ? here() : "'" + node.name + "'"));
    expect('(', "after " + node.name);
    arguments(node);
    if (take('{')) {
      while (!take('}')) {
        if (pos_ >= text_.size()) fail("the { of " + node.name + " is not closed");
        statement(node.children, depth + 1);
      }
    } else {
      expect(';', "or '{' after " + node.name + "(...)");
    }
    siblings.push_back(std::move(node));
  }

  void expect(char c, const std::string& where) { expect(c, where.c_str()); }

  void arguments(CsgNode& node) {
    if (take(')')) return;
    while (true) {
      skipSpace();
      const std::size_t mark = pos_;
      const int markLine = line_;
      std::string key = name();
      if (!key.empty() && take('=')) {
        if (node.named.count(key)) fail(node.name + ": " + key + " is given twice");
        node.named[key] = value(0);
      } else {
        pos_ = mark, line_ = markLine;
        node.positional.push_back(value(0));
      }
      if (take(')')) return;
      expect(',', "or ')' between the arguments of " + node.name);
    }
  }

  CsgValue value(int depth) {
    if (depth > kMaxDepth) fail("vectors nested deeper than " + std::to_string(kMaxDepth));
    skipSpace();
    CsgValue v;
    if (pos_ >= text_.size()) fail("expected a value, found the end of the file");
    const char c = text_[pos_];
    if (c == '[') {
      ++pos_;
      v.kind = CsgValue::Kind::Vector;
      if (take(']')) return v;
      while (true) {
        v.items.push_back(value(depth + 1));
        if (take(']')) return v;
        expect(',', "or ']' in a vector");
      }
    }
    if (c == '"') return string();
    if (c == '-' || c == '+' || c == '.' || std::isdigit(static_cast<unsigned char>(c)))
      return number();
    const std::string word = name();
    if (word == "true" || word == "false") {
      v.kind = CsgValue::Kind::Boolean;
      v.boolean = word == "true";
      return v;
    }
    if (word == "undef") return v;
    if (word == "inf" || word == "nan") {
      v.kind = CsgValue::Kind::Number;
      v.number = word == "inf" ? INFINITY : NAN;
      return v;
    }
    fail("expected a value, found " + (word.empty() ? here() : "'" + word + "'"));
  }

  CsgValue number() {
    CsgValue v;
    v.kind = CsgValue::Kind::Number;
    const char* begin = text_.c_str() + pos_;
    char* end = nullptr;
    v.number = std::strtod(begin, &end);
    if (end == begin) {
      // "-inf" and "-nan" are what OpenSCAD writes for those numbers.
      const bool negative = *begin == '-';
      if (text_.compare(pos_ + 1, 3, "inf") == 0 || text_.compare(pos_ + 1, 3, "nan") == 0) {
        v.number = text_.compare(pos_ + 1, 3, "inf") == 0 ? (negative ? -INFINITY : INFINITY) : NAN;
        pos_ += 4;
        return v;
      }
      fail("expected a number, found " + here());
    }
    pos_ += std::size_t(end - begin);
    return v;
  }

  CsgValue string() {
    CsgValue v;
    v.kind = CsgValue::Kind::String;
    ++pos_;  // the opening quote
    while (true) {
      if (pos_ >= text_.size()) fail("a string is not closed");
      const char c = text_[pos_++];
      if (c == '"') return v;
      if (c == '\n') ++line_;
      if (c == '\\' && pos_ < text_.size()) {
        const char e = text_[pos_++];
        v.text += e == 'n' ? '\n' : e == 't' ? '\t' : e == 'r' ? '\r' : e;
      } else {
        v.text += c;
      }
    }
  }

  const std::string& text_;
  const std::string& file_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

void appendKey(const CsgValue& value, std::string& key) {
  switch (value.kind) {
    case CsgValue::Kind::Undef:
      key += 'u';
      break;
    case CsgValue::Kind::Number: {
      char digits[32];  // %a: every bit of the double
      std::snprintf(digits, sizeof digits, "n%a", value.number);
      key += digits;
      break;
    }
    case CsgValue::Kind::Boolean:
      key += value.boolean ? 't' : 'f';
      break;
    case CsgValue::Kind::String:
      // Its length first, so that no string can end the key early.
      key += 's' + std::to_string(value.text.size()) + ':' + value.text;
      break;
    case CsgValue::Kind::Vector:
      key += '[';
      for (const CsgValue& item : value.items) appendKey(item, key);
      key += ']';
      break;
  }
}

void appendKey(const CsgNode& node, std::string& key) {
  key += node.name;
  if (node.modifier) key += node.modifier;
  key += '(';
  for (const CsgValue& v : node.positional) appendKey(v, key);
  for (const auto& [name, v] : node.named) {
    key += name + '=';
    appendKey(v, key);
  }
  key += "){";
  for (const CsgNode& child : node.children) appendKey(child, key);
  key += '}';
}

}  // namespace

std::string csgNodeKey(const CsgNode& node) {
  std::string key;
  appendKey(node, key);
  return key;
}

std::vector<CsgNode> parseCsg(const std::string& text, const std::string& fileName) {
  return Parser(text, fileName).file();
}

}  // namespace csgray::detail
