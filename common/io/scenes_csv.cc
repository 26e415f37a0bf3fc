#include "common/io/scenes_csv.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "common/io/atomic_file.h"
#include "common/io/data_error.h"

namespace giocal {

void writeScenesCsv(const std::string& path, const std::vector<SceneSpan>& scenes) {
  AtomicFile out(path);
  out.stream() << "t_start,t_end,type\n" << std::setprecision(15);
  for (const SceneSpan& s : scenes)
    out.stream() << s.t_start << "," << s.t_end << "," << s.type << "\n";
  out.commit();
}

std::vector<SceneSpan> readScenesCsv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw DataError(path, 0, "cannot open");
  std::string line;
  if (!std::getline(in, line) || line != "t_start,t_end,type") {
    throw DataError(path, 1, "header must be t_start,t_end,type");
  }
  std::vector<SceneSpan> out;
  for (long n = 2; std::getline(in, line); ++n) {
    if (line.empty()) continue;
    std::istringstream row(line);
    std::string a, b;
    SceneSpan s;
    std::getline(row, a, ',');
    std::getline(row, b, ',');
    std::getline(row, s.type);
    try {
      size_t ua = 0, ub = 0;
      s.t_start = std::stod(a, &ua);
      s.t_end = std::stod(b, &ub);
      if (ua != a.size() || ub != b.size()) throw std::invalid_argument("trailing text");
    } catch (const std::exception&) {
      throw DataError(path, n, "t_start and t_end must be numbers: '" + line + "'");
    }
    if (!std::isfinite(s.t_start) || !(s.t_end > s.t_start) || s.type.empty()) {
      throw DataError(path, n, "needs finite t_start < t_end and a type: '" + line + "'");
    }
    out.push_back(s);
  }
  return out;
}

std::string sceneAt(const std::vector<SceneSpan>& scenes, double t) {
  for (const SceneSpan& s : scenes) {
    if (t >= s.t_start && t < s.t_end) return s.type;
  }
  return "";
}

}  // namespace giocal
