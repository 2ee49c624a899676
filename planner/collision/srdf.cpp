#include "planner/collision/srdf.h"

#include <tinyxml.h>

#include "planner/util/input_error.h"
#include "planner/util/text_file.h"

namespace stanceplan {
namespace {

std::string where(const std::string& name, const TiXmlNode& node) {
  return name + ":" + std::to_string(node.Row()) + ": ";
}

std::vector<DisabledCollision> read_document(const TiXmlDocument& document,
                                             const std::string& name) {
  const TiXmlElement* robot = document.RootElement();
  if (robot == nullptr || std::string(robot->Value()) != "robot") {
    throw InputError(name + ": not an SRDF file: the root element must be <robot>");
  }
  std::vector<DisabledCollision> pairs;
  for (const TiXmlElement* e = robot->FirstChildElement("disable_collisions"); e != nullptr;
       e = e->NextSiblingElement("disable_collisions")) {
    const char* link1 = e->Attribute("link1");
    const char* link2 = e->Attribute("link2");
    if (link1 == nullptr || link2 == nullptr || *link1 == '\0' || *link2 == '\0') {
      throw InputError(where(name, *e) +
                       "<disable_collisions>: expected attributes link1 and link2");
    }
    const char* reason = e->Attribute("reason");
    pairs.push_back({link1, link2, reason != nullptr ? reason : ""});
  }
  return pairs;
}

}  // namespace

std::vector<DisabledCollision> parse_srdf_disabled_collisions(const std::string& xml,
                                                              const std::string& display_name) {
  TiXmlDocument document;
  document.Parse(xml.c_str());
  if (document.Error()) {
    throw InputError(display_name + ":" + std::to_string(document.ErrorRow()) +
                     ": malformed XML: " + document.ErrorDesc());
  }
  return read_document(document, display_name);
}

std::vector<DisabledCollision> load_srdf_disabled_collisions(const std::string& path) {
  return parse_srdf_disabled_collisions(read_text_file(path), path);
}

}  // namespace stanceplan
