#include "options/giocal_config.h"

#include "common/io/yaml_fields.h"

namespace giocal {

GiocalConfig readGiocalConfig(const std::string& path) {
  GiocalConfig c;
  // Without a file, an empty document: every option read at its default and recorded as such.
  const YamlFields y =
      path.empty() ? YamlFields("(defaults)", YAML::Node(YAML::NodeType::Map)) : YamlFields(path);
  c.calibration = readCalibrationOptions(y);
  c.fgo = readFgoOptions(y);
  c.rtk = readRtkOptions(y);
  y.rejectUnknownKeys();
  c.in_effect = y.inEffect();
  return c;
}

}  // namespace giocal
