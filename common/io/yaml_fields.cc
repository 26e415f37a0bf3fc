#include "common/io/yaml_fields.h"

#include <yaml-cpp/depthguard.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "common/io/data_error.h"
#include "common/io/nearest_name.h"

namespace giocal {

namespace {

/// Dotted keys of the leaves (scalars and lists) under `node`, with their nodes.
void leaves(const std::string& path, const YAML::Node& node, const std::string& prefix,
            std::vector<std::pair<std::string, YAML::Node>>& out) {
  if (!node.IsMap()) {
    out.push_back({prefix, node});
    return;
  }
  for (const auto& kv : node) {
    if (!kv.first.IsScalar()) {
      const long line = kv.first.Mark().line >= 0 ? kv.first.Mark().line + 1 : 0;
      throw DataError(path, line,
                      "a key under '" + (prefix.empty() ? std::string("the top level") : prefix) +
                          "' is a list or a map; keys must be plain names");
    }
    const std::string key = (prefix.empty() ? "" : prefix + ".") + kv.first.Scalar();
    leaves(path, kv.second, key, out);
  }
}

const char* kindOf(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Null:
      return "empty";
    case YAML::NodeType::Scalar:
      return "a single value";
    case YAML::NodeType::Sequence:
      return "a list";
    default:
      return "not a map";
  }
}

std::vector<std::string> splitKey(const std::string& key) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream ss(key);
  while (std::getline(ss, part, '.')) parts.push_back(part);
  return parts;
}
}  // namespace

YamlFields::YamlFields(const std::string& path) : path_(path) {
  try {
    root_ = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw DataError(path, 0, "cannot open file");
  } catch (const YAML::DeepRecursion& e) {
    // yaml-cpp's own message for this is "bad file", which says nothing.
    throw DataError(path, e.mark.line + 1,
                    "YAML nested too deeply (giocal's files are at most a few levels deep)");
  } catch (const YAML::Exception& e) {
    throw DataError(path, e.mark.line + 1, "YAML syntax error: " + e.msg);
  }
  if (!root_.IsMap()) {
    throw DataError(path, lineOf(root_) > 0 ? lineOf(root_) : 1,
                    std::string("the document is ") + kindOf(root_) +
                        "; expected a map of keys (key: value) at the top level");
  }
  // Keys that are lists or maps would surface later as a bad conversion inside yaml-cpp.
  std::vector<std::pair<std::string, YAML::Node>> keys;
  leaves(path, root_, "", keys);
}

YamlFields::YamlFields(const std::string& path, YAML::Node root) : path_(path), root_(root) {}

long YamlFields::lineOf(const YAML::Node& node) const {
  return node.Mark().line >= 0 ? node.Mark().line + 1 : 0;
}

void YamlFields::fail(const std::string& key, const std::string& problem) const {
  long line = 0;
  if (has(key)) line = lineOf(find(key));
  throw DataError(path_, line, "'" + key + "': " + problem);
}

YAML::Node YamlFields::find(const std::string& key) const {
  asked_.insert(key);
  // yaml-cpp's operator[] on a const node never inserts, but reassigning a Node rebinds it in
  // place, so walk with fresh copies.
  std::vector<YAML::Node> chain{root_};
  for (const auto& part : splitKey(key)) {
    const YAML::Node& cur = chain.back();
    if (!cur.IsMap() || !cur[part]) {
      throw DataError(path_, lineOf(cur), "missing key '" + key + "'");
    }
    chain.push_back(cur[part]);
  }
  return chain.back();
}

bool YamlFields::has(const std::string& key) const {
  asked_.insert(key);
  std::vector<YAML::Node> chain{root_};
  for (const auto& part : splitKey(key)) {
    const YAML::Node& cur = chain.back();
    if (!cur.IsMap() || !cur[part]) return false;
    chain.push_back(cur[part]);
  }
  return !chain.back().IsNull();
}

double YamlFields::number(const std::string& key) const {
  const YAML::Node node = find(key);
  double v = 0.0;
  if (!node.IsScalar() || !YAML::convert<double>::decode(node, v)) {
    throw DataError(path_, lineOf(node), "'" + key + "' must be a number");
  }
  if (!std::isfinite(v)) throw DataError(path_, lineOf(node), "'" + key + "' is not finite");
  return v;
}

double YamlFields::number(const std::string& key, double min, double max) const {
  const double v = number(key);
  if (v < min || v > max) {
    std::ostringstream msg;
    msg << "value " << v << " outside [" << min << ", " << max << "]";
    fail(key, msg.str());
  }
  return v;
}

double YamlFields::numberOr(const std::string& key, double fallback, double min, double max) const {
  const double v = has(key) ? number(key, min, max) : fallback;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  in_effect_[key] = buf;
  return v;
}

std::string YamlFields::text(const std::string& key) const {
  const YAML::Node node = find(key);
  if (!node.IsScalar()) throw DataError(path_, lineOf(node), "'" + key + "' must be a string");
  return in_effect_[key] = node.as<std::string>();
}

std::string YamlFields::textOr(const std::string& key, const std::string& fallback) const {
  return has(key) ? text(key) : in_effect_[key] = fallback;
}

bool YamlFields::flagOr(const std::string& key, bool fallback) const {
  if (!has(key)) {
    in_effect_[key] = fallback ? "true" : "false";
    return fallback;
  }
  const YAML::Node node = find(key);
  const std::string v = node.IsScalar() ? node.as<std::string>() : "";
  if (v != "true" && v != "false") {
    throw DataError(path_, lineOf(node), "'" + key + "' must be true or false");
  }
  in_effect_[key] = v;
  return v == "true";
}

std::vector<std::string> YamlFields::textList(const std::string& key, bool allow_empty) const {
  const YAML::Node node = find(key);
  if (node.IsScalar()) return {node.as<std::string>()};
  if (!node.IsSequence() || (node.size() == 0 && !allow_empty)) {
    throw DataError(path_, lineOf(node), "'" + key + "' must be a string or a list of strings");
  }
  std::vector<std::string> out;
  for (const auto& item : node) {
    if (!item.IsScalar())
      throw DataError(path_, lineOf(item), "'" + key + "' items must be strings");
    out.push_back(item.as<std::string>());
  }
  return out;
}

Eigen::VectorXd YamlFields::numberList(const std::string& key, int n) const {
  const YAML::Node node = find(key);
  const std::string what =
      "'" + key + "' must be a list of " + std::to_string(n) + " finite numbers";
  if (!node.IsSequence() || static_cast<int>(node.size()) != n) {
    throw DataError(path_, lineOf(node), what);
  }
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) {
    if (!YAML::convert<double>::decode(node[i], v[i]) || !std::isfinite(v[i])) {
      throw DataError(path_, lineOf(node), what);
    }
  }
  return v;
}

Eigen::Vector4d YamlFields::vector4(const std::string& key) const { return numberList(key, 4); }

Eigen::Vector3d YamlFields::vector3(const std::string& key) const { return numberList(key, 3); }

Eigen::Vector3d YamlFields::vector3(const std::string& key, double min, double max) const {
  const Eigen::Vector3d v = vector3(key);
  if (v.minCoeff() < min || v.maxCoeff() > max) {
    std::ostringstream msg;
    msg << "values outside [" << min << ", " << max << "]";
    fail(key, msg.str());
  }
  return v;
}

void YamlFields::rejectUnknownKeys(const std::vector<std::string>& other_sections) const {
  std::vector<std::pair<std::string, YAML::Node>> keys;
  leaves(path_, root_, "", keys);
  for (const auto& [key, node] : keys) {
    if (asked_.count(key)) continue;
    const std::string section = key.substr(0, key.find('.'));
    if (std::find(other_sections.begin(), other_sections.end(), section) != other_sections.end())
      continue;
    // Suggest only close spellings.
    const std::string nearest =
        nearestName(key, std::vector<std::string>(asked_.begin(), asked_.end()), 3);
    throw DataError(path_, lineOf(node),
                    "unknown key '" + key + "'" +
                        (nearest.empty() ? std::string(" (not a giocal option)")
                                         : "; did you mean '" + nearest + "'?"));
  }
}

}  // namespace giocal
