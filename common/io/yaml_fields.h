// YamlFields: typed, checked access to the keys of a YAML file, with "file:line: problem" errors.
#pragma once

#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace giocal {

class YamlFields {
 public:
  /// Loads `path`; throws DataError on a missing file or a YAML syntax error.
  explicit YamlFields(const std::string& path);
  /// Wraps an already parsed node (for tests and nested documents).
  YamlFields(const std::string& path, YAML::Node root);

  const YAML::Node& root() const { return root_; }
  const std::string& path() const { return path_; }

  /// `key` is a dotted path such as "imu.gyro_noise_density".
  bool has(const std::string& key) const;
  double number(const std::string& key) const;
  /// A number within [min, max]; the range names the physical limits of the field.
  double number(const std::string& key, double min, double max) const;
  double numberOr(const std::string& key, double fallback, double min, double max) const;
  std::string text(const std::string& key) const;
  std::string textOr(const std::string& key, const std::string& fallback) const;
  /// true or false; throws DataError naming the line for anything else.
  bool flagOr(const std::string& key, bool fallback) const;
  std::vector<std::string> textList(const std::string& key, bool allow_empty = false) const;
  Eigen::Vector3d vector3(const std::string& key) const;
  Eigen::Vector3d vector3(const std::string& key, double min, double max) const;
  Eigen::Vector4d vector4(const std::string& key) const;
  /// A list of exactly n finite numbers.
  Eigen::VectorXd numberList(const std::string& key, int n) const;

  [[noreturn]] void fail(const std::string& key, const std::string& problem) const;

  /// Every key read through numberOr / textOr / text with the value in effect, the file's or the
  /// default (for the run's record of its options).
  const std::map<std::string, std::string>& inEffect() const { return in_effect_; }

  /// Throws DataError at the first key of the file that no reader has asked for (a misspelling
  /// or a key of another version), naming the line, the key and the nearest known key. Keys under
  /// `other_sections` (top-level names) belong to other readers and are not checked.
  void rejectUnknownKeys(const std::vector<std::string>& other_sections = {}) const;

 private:
  YAML::Node find(const std::string& key) const;  // throws when missing
  long lineOf(const YAML::Node& node) const;

  std::string path_;
  YAML::Node root_;
  mutable std::set<std::string> asked_;  // every key looked up, present or not
  mutable std::map<std::string, std::string> in_effect_;
};

}  // namespace giocal
