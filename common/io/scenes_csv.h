// scenes.csv: the stretches of a drive with their own sky (open_sky, few_trees, more_trees,
// building), in GPS time; the simulator writes it, report and the fix audit read it.
#pragma once

#include <string>
#include <vector>

namespace giocal {

struct SceneSpan {
  double t_start = 0.0, t_end = 0.0;  // GPS seconds
  std::string type;
};

/// Writes `t_start,t_end,type` rows atomically.
void writeScenesCsv(const std::string& path, const std::vector<SceneSpan>& scenes);

/// Throws DataError naming the file and line for a bad header, row or an empty span.
std::vector<SceneSpan> readScenesCsv(const std::string& path);

/// The type of the scene holding t, or "" outside every scene.
std::string sceneAt(const std::vector<SceneSpan>& scenes, double t);

}  // namespace giocal
