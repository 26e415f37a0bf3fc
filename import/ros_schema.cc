#include "import/ros_schema.h"

#include <set>
#include <sstream>
#include <stdexcept>

namespace giocal::import {

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::string packageOf(const std::string& type) {
  const auto slash = type.find('/');
  return slash == std::string::npos ? "" : type.substr(0, slash);
}

// "pkg/msg/Type" (ROS 2) and "pkg/Type" (ROS 1) name the same type.
std::string canonical(const std::string& type) {
  const auto first = type.find('/');
  const auto last = type.rfind('/');
  if (first != last && type.substr(first, last - first + 1) == "/msg/") {
    return type.substr(0, first) + type.substr(last);
  }
  return type;
}

}  // namespace

bool isRosPrimitive(const std::string& type) {
  static const std::set<std::string> kPrimitives{
      "bool",    "int8",    "uint8",  "int16", "uint16",   "int32", "uint32", "int64",  "uint64",
      "float32", "float64", "string", "time",  "duration", "char",  "byte",   "wstring"};
  return kPrimitives.count(type) > 0;
}

RosSchema::RosSchema(const std::string& root_type, const std::string& definition)
    : root_(canonical(root_type)) {
  // Split into sections: the root's, then one per "MSG: pkg/Type" line.
  std::map<std::string, std::vector<std::pair<int, std::string>>> sections;
  std::string current = root_;
  std::istringstream in(definition);
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string t = trim(line.substr(0, line.find('#')));
    if (t.rfind("MSG:", 0) == 0) {
      current = canonical(trim(t.substr(4)));
      sections[current];
      continue;
    }
    if (t.empty() || t.rfind("===", 0) == 0) continue;
    sections[current].push_back({line_no, t});
  }
  auto resolve = [&](const std::string& type, const std::string& in_type, int at) {
    if (isRosPrimitive(type)) return type;
    if (type == "Header") return std::string("std_msgs/Header");
    if (type.find('/') != std::string::npos) return canonical(type);
    const std::string same_package = packageOf(in_type) + "/" + type;
    if (sections.count(same_package)) return same_package;
    for (const auto& [name, lines] : sections) {
      if (name.size() > type.size() &&
          name.compare(name.size() - type.size() - 1, std::string::npos, "/" + type) == 0) {
        return name;
      }
    }
    throw std::runtime_error("definition of " + root_ + ", line " + std::to_string(at) +
                             ": type '" + type + "' is not defined");
  };
  for (const auto& [type, lines] : sections) {
    auto& fields = types_[type];
    for (const auto& [at, text] : lines) {
      std::istringstream words(text);
      std::string type_text, name;
      words >> type_text >> name;
      if (name.empty()) {
        throw std::runtime_error("definition of " + root_ + ", line " + std::to_string(at) + ": '" +
                                 text + "' is not 'type name'");
      }
      if (name.find('=') != std::string::npos || text.find('=') != std::string::npos) continue;
      RosField f;
      f.name = name;
      const auto bracket = type_text.find('[');
      if (bracket != std::string::npos) {
        const std::string n = type_text.substr(bracket + 1, type_text.size() - bracket - 2);
        // "<=N" is a ROS 2 bounded sequence: variable length on the wire.
        f.array = n.empty() || n[0] == '<' ? 0 : std::stoi(n);
        if (f.array < 0 || f.array > 1 << 20) {
          throw std::runtime_error("definition of " + root_ + ", line " + std::to_string(at) +
                                   ": array length " + n);
        }
        type_text = type_text.substr(0, bracket);
      }
      const auto bound = type_text.find("<=");  // ROS 2 bounded string
      if (bound != std::string::npos) type_text = type_text.substr(0, bound);
      f.type = resolve(type_text, type, at);
      fields.push_back(f);
    }
  }
  if (!types_.count(root_)) throw std::runtime_error("definition of " + root_ + " is empty");
}

const std::vector<RosField>& RosSchema::fieldsOf(const std::string& type) const {
  const auto it = types_.find(type);
  if (it == types_.end()) throw std::runtime_error("definition of " + root_ + " lacks " + type);
  return it->second;
}

}  // namespace giocal::import
