// A small reader of XML documents, enough for SVG drawings
// (profile/svg_reader): the tree of elements and their attributes, each
// with the line it starts on. Comments, processing instructions (the XML
// declaration among them), CDATA sections and text are read and dropped;
// a DOCTYPE is skipped, but the general entities its internal subset
// declares (<!ENTITY name "value">, as Adobe Illustrator writes its
// namespaces) are kept. Attribute values have their references replaced:
// the five predefined entities (&lt; &gt; &amp; &apos; &quot;), numeric
// character references (&#38; &#x26;, written as UTF-8) and the declared
// entities (their values taken as they are, not expanded again, so that a
// file cannot make a reference grow without bound).
//
// The format: W3C, "Extensible Markup Language (XML) 1.0", 5th ed., 2008
// (https://www.w3.org/TR/xml/), sections 2.4 to 2.8, 3.1, 4.1 and 4.6.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace csgray::detail {

struct XmlAttribute {
  std::string name;   // as written, with its prefix: "xlink:href"
  std::string value;  // references replaced
  int line = 0;
};

struct XmlElement {
  std::string name;  // as written, with its prefix: "svg:path"
  int line = 0;
  std::vector<XmlAttribute> attributes;
  std::vector<XmlElement> children;

  // The attribute's value, or nullptr when the element has none of that name.
  const XmlAttribute* attribute(std::string_view attributeName) const;
};

// The document's root element. Throws std::invalid_argument "file:line:
// what" for text that is not well-formed XML: a tag or comment left open,
// an end tag that does not match, an attribute without a quoted value or
// given twice, an unknown entity, text or a second element after the root,
// no root at all, or elements nested deeper than 256.
XmlElement readXml(std::string_view text, const std::string& fileName);

}  // namespace csgray::detail
