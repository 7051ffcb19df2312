#include "profile/xml_reader.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <stdexcept>

namespace csgray::detail {

namespace {

constexpr std::size_t kMaxDepth = 256;

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

// Name characters (XML 1.0, 2.3), with every byte of a multi-byte UTF-8
// character allowed.
bool isNameChar(char c) {
  const auto u = static_cast<unsigned char>(c);
  return u >= 0x80 || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
         c == '_' || c == ':' || c == '-' || c == '.';
}

void appendUtf8(std::string& out, std::uint32_t code) {
  if (code < 0x80) {
    out += char(code);
  } else if (code < 0x800) {
    out += char(0xC0 | (code >> 6));
    out += char(0x80 | (code & 0x3F));
  } else if (code < 0x10000) {
    out += char(0xE0 | (code >> 12));
    out += char(0x80 | ((code >> 6) & 0x3F));
    out += char(0x80 | (code & 0x3F));
  } else {
    out += char(0xF0 | (code >> 18));
    out += char(0x80 | ((code >> 12) & 0x3F));
    out += char(0x80 | ((code >> 6) & 0x3F));
    out += char(0x80 | (code & 0x3F));
  }
}

class XmlReader {
 public:
  XmlReader(std::string_view text, const std::string& fileName) : text_(text), file_(fileName) {}

  XmlElement read() {
    // A byte order mark before the document.
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") at_ = 3;
    std::vector<XmlElement> open;  // the elements started and not yet ended
    bool haveRoot = false;
    XmlElement root;
    while (at_ < text_.size()) {
      if (text_[at_] != '<') {
        const int line = line_;
        const bool blank = skipText();
        if (open.empty() && !blank) fail(line, "text outside the root element");
        continue;
      }
      if (startsWith("<!--")) {
        skipPast("-->", "a comment");
      } else if (startsWith("<?")) {
        skipPast("?>", "a processing instruction");
      } else if (startsWith("<![CDATA[")) {
        if (open.empty()) fail(line_, "a CDATA section outside the root element");
        skipPast("]]>", "a CDATA section");
      } else if (startsWith("<!DOCTYPE")) {
        if (haveRoot || !open.empty()) fail(line_, "a DOCTYPE after the root element started");
        doctype();
      } else if (startsWith("</")) {
        const int line = line_;
        at_ += 2;
        const std::string name = readName("an end tag");
        skipSpace();
        expect('>', "'>' to close the end tag </" + name);
        if (open.empty()) fail(line, "the end tag </" + name + "> closes no element");
        if (open.back().name != name)
          fail(line, "the end tag </" + name + "> does not match <" + open.back().name +
                         "> (line " + std::to_string(open.back().line) + ")");
        XmlElement done = std::move(open.back());
        open.pop_back();
        if (open.empty()) {
          root = std::move(done);
          haveRoot = true;
        } else {
          open.back().children.push_back(std::move(done));
        }
      } else {
        if (haveRoot) fail(line_, "a second root element");
        bool empty = false;
        XmlElement element = startTag(empty);
        if (open.size() >= kMaxDepth)
          fail(element.line, "elements nested deeper than " + std::to_string(kMaxDepth));
        if (!empty) {
          open.push_back(std::move(element));
        } else if (open.empty()) {
          root = std::move(element);
          haveRoot = true;
        } else {
          open.back().children.push_back(std::move(element));
        }
      }
    }
    if (!open.empty())
      fail(open.back().line,
           "<" + open.back().name + "> is not closed: the file ends first (is it cut short?)");
    if (!haveRoot) throw std::invalid_argument(file_ + ": not an XML document (it has no element)");
    return root;
  }

 private:
  [[noreturn]] void fail(int line, const std::string& what) const {
    throw std::invalid_argument(file_ + ":" + std::to_string(line) + ": " + what);
  }

  bool startsWith(std::string_view s) const { return text_.substr(at_, s.size()) == s; }

  void advance() {
    if (text_[at_] == '\n') ++line_;
    ++at_;
  }

  void skipSpace() {
    while (at_ < text_.size() && isSpace(text_[at_])) advance();
  }

  void expect(char c, const std::string& what) {
    if (at_ >= text_.size() || text_[at_] != c) fail(line_, "expected " + what);
    advance();
  }

  // Skips character data up to the next '<'; is it only white space?
  bool skipText() {
    bool blank = true;
    while (at_ < text_.size() && text_[at_] != '<') {
      blank &= isSpace(text_[at_]);
      advance();
    }
    return blank;
  }

  void skipPast(std::string_view end, const char* what) {
    const int line = line_;
    const std::size_t found = text_.find(end, at_);
    if (found == std::string_view::npos)
      fail(line, std::string(what) + " is not closed (is the file cut short?)");
    while (at_ < found + end.size()) advance();
  }

  std::string readName(const char* where) {
    const std::size_t start = at_;
    while (at_ < text_.size() && isNameChar(text_[at_])) ++at_;
    if (at_ == start) {
      if (at_ >= text_.size()) fail(line_, "the file ends in " + std::string(where));
      fail(line_, "expected a name in " + std::string(where) + ", found " +
                      (isSpace(text_[at_]) ? std::string("white space")
                                           : "'" + std::string(1, text_[at_]) + "'"));
    }
    return std::string(text_.substr(start, at_ - start));
  }

  // A quoted value, its references replaced.
  std::string quoted(const std::string& what) {
    skipSpace();
    if (at_ >= text_.size() || (text_[at_] != '"' && text_[at_] != '\''))
      fail(line_, what + " has no quoted value");
    const char quote = text_[at_];
    const int line = line_;
    advance();
    std::string value;
    while (at_ < text_.size() && text_[at_] != quote) {
      if (text_[at_] == '<') fail(line_, "'<' in the value of " + what);
      if (text_[at_] == '&') {
        reference(value);
        continue;
      }
      value += text_[at_];
      advance();
    }
    if (at_ >= text_.size()) fail(line, "the value of " + what + " is not closed");
    advance();
    return value;
  }

  // A reference at '&' (XML 1.0, 4.1), replaced into out.
  void reference(std::string& out) {
    const int line = line_;
    const std::size_t semicolon = text_.find(';', at_);
    if (semicolon == std::string_view::npos || semicolon - at_ > 40)
      fail(line, "an '&' that starts no reference (write &amp; for '&')");
    const std::string_view name = text_.substr(at_ + 1, semicolon - at_ - 1);
    if (name.empty() ||
        !std::all_of(name.begin(), name.end(), [](char c) { return isNameChar(c) || c == '#'; }))
      fail(line, "an '&' that starts no reference (write &amp; for '&')");
    while (at_ <= semicolon) advance();
    if (!name.empty() && name[0] == '#') {
      const bool hex = name.size() > 1 && name[1] == 'x';
      const std::string_view digits = name.substr(hex ? 2 : 1);
      std::uint32_t code = 0;
      bool valid = !digits.empty();
      for (char c : digits) {
        const int d = c >= '0' && c <= '9'          ? c - '0'
                      : hex && c >= 'a' && c <= 'f' ? c - 'a' + 10
                      : hex && c >= 'A' && c <= 'F' ? c - 'A' + 10
                                                    : -1;
        if (d < 0) valid = false;
        code = code * (hex ? 16 : 10) + std::uint32_t(d < 0 ? 0 : d);
        if (code > 0x10FFFF) valid = false;
        if (!valid) break;
      }
      if (!valid || code == 0 || (code >= 0xD800 && code <= 0xDFFF))
        fail(line, "&" + std::string(name) + "; is not a character");
      appendUtf8(out, code);
      return;
    }
    static const std::map<std::string_view, char> predefined = {
        {"lt", '<'}, {"gt", '>'}, {"amp", '&'}, {"apos", '\''}, {"quot", '"'}};
    if (auto it = predefined.find(name); it != predefined.end()) {
      out += it->second;
      return;
    }
    if (auto it = entities_.find(std::string(name)); it != entities_.end()) {
      out += it->second;
      return;
    }
    fail(line, "the entity &" + std::string(name) + "; is not declared");
  }

  XmlElement startTag(bool& empty) {
    XmlElement element;
    element.line = line_;
    ++at_;  // '<'
    element.name = readName("a start tag");
    while (true) {
      const std::size_t before = at_;
      skipSpace();
      if (at_ >= text_.size())
        fail(element.line, "the tag <" + element.name + " is not closed (is the file cut short?)");
      if (text_[at_] == '>') {
        advance();
        return element;
      }
      if (startsWith("/>")) {
        at_ += 2;
        empty = true;
        return element;
      }
      if (at_ == before) fail(line_, "expected a space between the attributes of <" + element.name);
      XmlAttribute attribute;
      attribute.line = line_;
      attribute.name = readName(("the tag <" + element.name).c_str());
      skipSpace();
      expect('=', "'=' after the attribute " + attribute.name);
      attribute.value = quoted("the attribute " + attribute.name);
      if (element.attribute(attribute.name))
        fail(attribute.line, "the attribute " + attribute.name + " is given twice");
      element.attributes.push_back(std::move(attribute));
    }
  }

  // <!DOCTYPE name (SYSTEM|PUBLIC "..." "...")? [internal subset]? >: the
  // general entities of the internal subset are kept, the rest skipped.
  void doctype() {
    const int line = line_;
    at_ += 9;
    skipUntilOneOf(">[");
    if (at_ < text_.size() && text_[at_] == '[') {
      advance();
      while (true) {
        skipSpace();
        if (at_ >= text_.size()) break;
        if (text_[at_] == ']') {
          advance();
          break;
        }
        if (startsWith("<!--")) {
          skipPast("-->", "a comment");
        } else if (startsWith("<!ENTITY")) {
          entityDeclaration();
        } else if (text_[at_] == '<') {
          markupDeclaration();
        } else {
          advance();  // a parameter-entity reference: %name;
        }
      }
      skipSpace();
    }
    if (at_ >= text_.size() || text_[at_] != '>')
      fail(line, "the DOCTYPE is not closed (is the file cut short?)");
    advance();
  }

  // An <!ELEMENT ...>, <!ATTLIST ...> or <?...?> in the internal subset:
  // skipped up to its '>' outside quotes.
  void markupDeclaration() {
    const int line = line_;
    skipUntilOneOf(">");
    if (at_ >= text_.size()) fail(line, "a declaration in the DOCTYPE is not closed");
    advance();
  }

  // Moves to the next of the characters outside quoted literals, or to the
  // end of the text.
  void skipUntilOneOf(std::string_view stops) {
    while (at_ < text_.size() && stops.find(text_[at_]) == std::string_view::npos) {
      if (text_[at_] == '"' || text_[at_] == '\'') {
        const char quote = text_[at_];
        advance();
        while (at_ < text_.size() && text_[at_] != quote) advance();
        if (at_ >= text_.size()) break;
      }
      advance();
    }
  }

  void entityDeclaration() {
    const int line = line_;
    at_ += 8;
    skipSpace();
    if (at_ < text_.size() && text_[at_] == '%') {  // a parameter entity
      markupDeclaration();
      return;
    }
    const std::string name = readName("an ENTITY declaration");
    skipSpace();
    if (at_ < text_.size() && (text_[at_] == '"' || text_[at_] == '\'')) {
      const char quote = text_[at_];
      advance();
      const std::size_t start = at_;
      while (at_ < text_.size() && text_[at_] != quote) advance();
      if (at_ >= text_.size()) fail(line, "the value of the entity " + name + " is not closed");
      std::string value(text_.substr(start, at_ - start));
      advance();
      // The first declaration of a name binds it (XML 1.0, 4.2).
      if (value.find('&') == std::string::npos && value.find('<') == std::string::npos)
        entities_.emplace(name, std::move(value));
    }
    markupDeclaration();  // an external entity's SYSTEM "..." and the '>'
  }

  std::string_view text_;
  const std::string& file_;
  std::size_t at_ = 0;
  int line_ = 1;
  std::map<std::string, std::string> entities_;
};

}  // namespace

const XmlAttribute* XmlElement::attribute(std::string_view attributeName) const {
  for (const XmlAttribute& a : attributes)
    if (a.name == attributeName) return &a;
  return nullptr;
}

XmlElement readXml(std::string_view text, const std::string& fileName) {
  return XmlReader(text, fileName).read();
}

}  // namespace csgray::detail
