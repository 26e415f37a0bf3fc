#include "replay/config.h"

#include "common/io/yaml_fields.h"

namespace giocal {

GiocalConfig readGiocalConfig(const std::string& path) {
  GiocalConfig c;
  if (path.empty()) return c;
  const YamlFields y(path);
  c.calibration = readCalibrationOptions(y);
  c.fgo = readFgoOptions(y);
  c.rtk = readRtkOptions(y);
  y.rejectUnknownKeys();
  return c;
}

}  // namespace giocal
