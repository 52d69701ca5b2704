#pragma once
/// \file
/// A strict little XML reader for the tests: parses a document into an element tree and throws
/// on anything that is not well-formed (unbalanced or mismatched tags, unquoted or repeated
/// attributes, a bare '&' or '<' in text, content after the root). Enough for XDMF files;
/// no namespaces, CDATA or DTD processing (an internal subset is skipped).

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace spar::test {

struct XmlElement {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::vector<XmlElement> children;
  std::string text;  ///< character data directly inside the element, entities decoded

  /// The children named `child_name`.
  std::vector<const XmlElement*> all(const std::string& child_name) const {
    std::vector<const XmlElement*> result;
    for (const XmlElement& child : children)
      if (child.name == child_name) result.push_back(&child);
    return result;
  }
  /// The one child named `child_name`; throws if there is none or more than one.
  const XmlElement& one(const std::string& child_name) const {
    const auto found = all(child_name);
    if (found.size() != 1)
      throw std::runtime_error("<" + name + "> has " + std::to_string(found.size()) + " <" + child_name + ">");
    return *found.front();
  }
  const std::string& attribute(const std::string& key) const {
    const auto it = attributes.find(key);
    if (it == attributes.end()) throw std::runtime_error("<" + name + "> has no attribute " + key);
    return it->second;
  }
};

class XmlReader {
public:
  /// The root element of `document`; throws std::runtime_error naming the offset of the fault.
  static XmlElement parse(const std::string& document) {
    XmlReader reader(document);
    reader.skip_prolog();
    XmlElement root = reader.element();
    reader.skip_misc();
    if (reader.at_ < document.size()) reader.fail("content after the root element");
    return root;
  }

private:
  explicit XmlReader(const std::string& document) : doc_(document) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("XML not well-formed at offset " + std::to_string(at_) + ": " + what);
  }
  bool starts(const char* token) const { return doc_.compare(at_, std::char_traits<char>::length(token), token) == 0; }
  void expect(const char* token) {
    if (!starts(token)) fail(std::string("expected '") + token + "'");
    at_ += std::char_traits<char>::length(token);
  }
  void skip_space() {
    while (at_ < doc_.size() && (doc_[at_] == ' ' || doc_[at_] == '\n' || doc_[at_] == '\t' || doc_[at_] == '\r')) ++at_;
  }
  void skip_past(const char* token) {
    const auto end = doc_.find(token, at_);
    if (end == std::string::npos) fail(std::string("unterminated, missing '") + token + "'");
    at_ = end + std::char_traits<char>::length(token);
  }
  /// Comments and white space.
  void skip_misc() {
    for (skip_space(); starts("<!--"); skip_space()) skip_past("-->");
  }
  /// The XML declaration, comments and a DOCTYPE (its internal subset in [ ] skipped).
  void skip_prolog() {
    if (starts("<?xml")) skip_past("?>");
    skip_misc();
    if (starts("<!DOCTYPE")) {
      int depth = 0;
      for (; at_ < doc_.size() && !(doc_[at_] == '>' && depth == 0); ++at_)
        depth += doc_[at_] == '[' ? 1 : doc_[at_] == ']' ? -1 : 0;
      expect(">");
    }
    skip_misc();
  }
  static bool name_char(char c, bool first) {
    const bool letter = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_' || c == ':';
    return letter || (!first && ((c >= '0' && c <= '9') || c == '-' || c == '.'));
  }
  std::string name() {
    const std::size_t begin = at_;
    while (at_ < doc_.size() && name_char(doc_[at_], at_ == begin)) ++at_;
    if (at_ == begin) fail("expected a name");
    return doc_.substr(begin, at_ - begin);
  }
  /// Character data up to one of `stops`, with the five predefined entities decoded.
  std::string characters(const char* stops) {
    std::string text;
    for (; at_ < doc_.size() && std::char_traits<char>::find(stops, std::char_traits<char>::length(stops), doc_[at_]) == nullptr; ++at_) {
      if (doc_[at_] == '<') fail("'<' in character data");
      if (doc_[at_] != '&') {
        text += doc_[at_];
        continue;
      }
      static const std::pair<const char*, char> entities[] = {
          {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
      bool known = false;
      for (const auto& [entity, character] : entities)
        if (starts(entity)) {
          text += character;
          at_ += std::char_traits<char>::length(entity) - 1;
          known = true;
          break;
        }
      if (!known) fail("bare '&' or unknown entity");
    }
    return text;
  }
  void attributes(XmlElement& element) {
    for (skip_space(); at_ < doc_.size() && doc_[at_] != '>' && doc_[at_] != '/'; skip_space()) {
      const std::string key = name();
      skip_space();
      expect("=");
      skip_space();
      if (at_ >= doc_.size() || (doc_[at_] != '"' && doc_[at_] != '\'')) fail("attribute value not quoted");
      const char quote[2] = {doc_[at_++], '\0'};
      std::string value = characters(quote);
      expect(quote);
      if (!element.attributes.emplace(key, std::move(value)).second) fail("attribute " + key + " repeated");
    }
  }
  XmlElement element() {
    expect("<");
    XmlElement result;
    result.name = name();
    attributes(result);
    if (starts("/>")) {
      at_ += 2;
      return result;
    }
    expect(">");
    while (true) {
      if (at_ >= doc_.size()) fail("<" + result.name + "> not closed");
      if (starts("</")) break;
      if (starts("<!--")) {
        skip_past("-->");
      } else if (starts("<")) {
        result.children.push_back(element());
      } else {
        result.text += characters("<");
      }
    }
    at_ += 2;
    if (name() != result.name) fail("closing tag does not match <" + result.name + ">");
    skip_space();
    expect(">");
    return result;
  }

  const std::string& doc_;
  std::size_t at_ = 0;
};

}  // namespace spar::test
