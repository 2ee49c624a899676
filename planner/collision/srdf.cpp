#include "planner/collision/srdf.h"

#include <tinyxml.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "planner/util/input_error.h"
#include "planner/util/text_file.h"
#include "planner/util/xml_buffer.h"

namespace stanceplan {
namespace {

std::string where(const std::string& name, const TiXmlNode& node) {
  return name + ":" + std::to_string(node.Row()) + ": ";
}

// Parses xml into *document and returns its <robot> root element.
const TiXmlElement& robot_element(const std::string& xml, const std::string& name,
                                  TiXmlDocument* document) {
  const std::string buffer = xml_parse_buffer(xml);  // NUL-padded: TinyXML reads past the end
  document->Parse(buffer.c_str());
  if (document->Error()) {
    throw InputError(name + ":" + std::to_string(document->ErrorRow()) +
                     ": malformed XML: " + document->ErrorDesc());
  }
  const TiXmlElement* robot = document->RootElement();
  if (robot == nullptr || std::string(robot->Value()) != "robot") {
    throw InputError(name + ": not an SRDF file: the root element must be <robot>");
  }
  return *robot;
}

std::vector<DisabledCollision> read_disabled_collisions(const TiXmlElement& robot,
                                                        const std::string& name) {
  std::vector<DisabledCollision> pairs;
  for (const TiXmlElement* e = robot.FirstChildElement("disable_collisions"); e != nullptr;
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

// A value attribute: whitespace-separated finite numbers ("0. 0. 1.01927 0. 0. 0. 1."); empty
// when the text is anything else.
std::vector<double> parse_values(const std::string& text) {
  std::vector<double> values;
  const char* p = text.c_str();
  for (;;) {
    while (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r') ++p;
    if (*p == '\0') return values;
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(p, &end);
    const bool separated =
        *end == '\0' || *end == ' ' || *end == '\t' || *end == '\n' || *end == '\r';
    if (end == p || errno == ERANGE || !std::isfinite(v) || !separated) return {};
    values.push_back(v);
    p = end;
  }
}

// A non-empty attribute of e, or an InputError "FILE:LINE: WHAT: expected attribute ATTRIBUTE".
std::string required(const TiXmlElement& e, const char* attribute, const std::string& name,
                     const std::string& what) {
  const char* value = e.Attribute(attribute);
  if (value == nullptr || *value == '\0')
    throw InputError(where(name, e) + what + ": expected attribute " + attribute);
  return value;
}

SrdfGroupState read_group_state(const TiXmlElement& e, const std::string& name) {
  SrdfGroupState state;
  state.name = required(e, "name", name, "<group_state>");
  const char* group = e.Attribute("group");
  state.group = group != nullptr ? group : "";
  state.line = e.Row();
  const std::string what = "<group_state name=\"" + state.name + "\"> <joint>";
  for (const TiXmlElement* j = e.FirstChildElement("joint"); j != nullptr;
       j = j->NextSiblingElement("joint")) {
    SrdfJointValue joint;
    joint.joint = required(*j, "name", name, what);
    const std::string text = required(*j, "value", name, what + " \"" + joint.joint + "\"");
    joint.values = parse_values(text);
    if (joint.values.empty())
      throw InputError(where(name, *j) + what + " \"" + joint.joint +
                       "\": value: expected finite numbers separated by spaces, found \"" + text +
                       "\"");
    joint.line = j->Row();
    state.joints.push_back(std::move(joint));
  }
  return state;
}

SrdfStates read_states(const TiXmlElement& robot, const std::string& name) {
  SrdfStates out;
  for (const TiXmlElement* e = robot.FirstChildElement("group_state"); e != nullptr;
       e = e->NextSiblingElement("group_state"))
    out.states.push_back(read_group_state(*e, name));
  for (const TiXmlElement* e = robot.FirstChildElement("virtual_joint"); e != nullptr;
       e = e->NextSiblingElement("virtual_joint")) {
    const char* type = e->Attribute("type");
    const char* joint = e->Attribute("name");
    if (type != nullptr && std::string(type) == "floating" && joint != nullptr)
      out.floating_joints.push_back(joint);
  }
  return out;
}

}  // namespace

std::vector<DisabledCollision> parse_srdf_disabled_collisions(const std::string& xml,
                                                              const std::string& display_name) {
  TiXmlDocument document;
  return read_disabled_collisions(robot_element(xml, display_name, &document), display_name);
}

std::vector<DisabledCollision> load_srdf_disabled_collisions(const std::string& path) {
  return parse_srdf_disabled_collisions(read_text_file(path), path);
}

SrdfStates parse_srdf_states(const std::string& xml, const std::string& display_name) {
  TiXmlDocument document;
  return read_states(robot_element(xml, display_name, &document), display_name);
}

SrdfStates load_srdf_states(const std::string& path) {
  return parse_srdf_states(read_text_file(path), path);
}

}  // namespace stanceplan
