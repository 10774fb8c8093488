// OMM in XML (CCSDS NDM/XML): an `ndm` root holding `omm` elements, or one `omm` root. Each omm's
// body/segment/metadata, data/meanElements and data/tleParameters children are its keywords.
#include <pugixml.hpp>

#include "orbit/elements_fields.h"
#include "orbit/elements_omm_internal.h"

namespace tb::orbit {

using detail::OmmObject;

namespace {

int line_of(std::string_view text, const pugi::xml_node& node) {
  const std::ptrdiff_t offset = node.offset_debug();
  return offset < 0 ? 0 : detail::line_of_offset(text, static_cast<std::size_t>(offset));
}

// The keywords of one `omm` element.
OmmObject xml_object(const pugi::xml_node& omm, std::string_view text, std::string_view file) {
  OmmObject o;
  o.line = line_of(text, omm);
  const pugi::xml_node segment = omm.child("body").child("segment");
  const pugi::xml_node data = segment.child("data");
  if (!segment || !data) {
    o.structural = detail::make_problem(file, o.line, 0, "omm/body/segment/data", "",
                                        "an omm element with body/segment/metadata and body/segment/data");
    return o;
  }
  for (const pugi::xml_node& group : {segment.child("metadata"), data.child("meanElements"),
                                      data.child("tleParameters")}) {
    for (const pugi::xml_node& field : group.children()) {
      if (field.type() != pugi::node_element) continue;
      o.fields.push_back({field.name(), std::string(text::trim(field.child_value(), text::kWhitespace)),
                          line_of(text, field)});
    }
  }
  return o;
}

}  // namespace

ParseResult parse_omm_xml(std::string_view text, std::string_view file_name) {
  ParseResult r;
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed = doc.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8);
  if (!parsed) {
    const std::size_t at = parsed.offset < 0 ? 0 : static_cast<std::size_t>(parsed.offset);
    r.problems.push_back(detail::make_problem(file_name, detail::line_of_offset(text, at), 0, "XML",
                                              std::string(text.substr(std::min(at, text.size()), 20)),
                                              std::string("well-formed XML (") + parsed.description() + ")"));
    return r;
  }
  const pugi::xml_node root = doc.document_element();
  std::vector<pugi::xml_node> omms;
  if (std::string_view(root.name()) == "omm") {
    omms.push_back(root);
  } else if (std::string_view(root.name()) == "ndm") {
    for (const pugi::xml_node& n : root.children("omm")) omms.push_back(n);
  }
  if (omms.empty()) {
    r.problems.push_back(detail::make_problem(file_name, line_of(text, root), 0, "XML root", root.name(),
                                              "an ndm element holding omm elements, or one omm element"));
    return r;
  }
  for (std::size_t i = 0; i < omms.size(); ++i)
    detail::add_omm_object(xml_object(omms[i], text, file_name), static_cast<int>(i + 1), file_name,
                           ElementFormat::omm_xml, r);
  return r;
}

}  // namespace tb::orbit
