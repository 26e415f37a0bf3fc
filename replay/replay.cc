#include "replay/replay.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <memory>

#include "common/calibration/dataset_diagnosis.h"
#include "common/gnss/pos_reader.h"
#include "common/gnss/rinex_obs.h"
#include "common/gnss/spp.h"
#include "common/io/data_error.h"
#include "common/io/sensor_logs.h"
#include "common/io/text.h"
#include "replay/estimator_factory.h"

namespace giocal {
namespace {

/// One time-ordered source: the time of the item it holds (infinity when exhausted) and a step
/// that hands that item to the calibrator and returns the time of the next.
struct Stream {
  double t = INFINITY;
  std::function<double()> step;
  long count = 0;
};

/// Hands every stream's items to the calibrator, oldest first, until they end or a stop is
/// requested (Interrupted).
void merge(std::vector<Stream>& streams, const StopRequest* stop) {
  while (true) {
    checkStop(stop);
    Stream* next = nullptr;
    for (Stream& s : streams) {
      if (s.t < INFINITY && (!next || s.t < next->t)) next = &s;
    }
    if (!next) return;
    next->t = next->step();
    ++next->count;
  }
}

/// A stream over a reader with bool next(T&), ordered by its times moved by `offset`
/// (dataset.yaml's time_offsets); the items go to the calibrator as read, which applies the offsets
/// itself.
template <class Reader, class T>
Stream readerStream(std::shared_ptr<Reader> reader, std::function<void(const T&)> push,
                    double offset = 0.0) {
  auto held = std::make_shared<T>();
  const auto next = [reader, held, offset]() -> double {
    if (!reader->next(*held)) return INFINITY;
    return held->t + offset;
  };
  Stream s;
  s.t = next();
  s.step = [held, push, next]() {
    push(*held);
    return next();
  };
  return s;
}

/// A stream over a vector, ordered by its times moved by `offset`.
template <class T>
Stream vectorStream(const std::vector<T>& v, std::function<void(const T&)> push,
                    double offset = 0.0) {
  Stream s;
  auto k = std::make_shared<size_t>(0);
  s.t = v.empty() ? INFINITY : v.front().t + offset;
  s.step = [&v, k, push, offset]() {
    push(v[(*k)++]);
    return *k < v.size() ? v[*k].t + offset : INFINITY;
  };
  return s;
}

Eigen::Vector3d basePosition(const DatasetDescription& d, const ObsHeader& base_header) {
  const Eigen::Vector3d p =
      d.base_position_ecef ? *d.base_position_ecef : base_header.approx_position;
  if (p.norm() < 6.0e6) {
    throw DataError(d.pathOf(d.base_obs), 0,
                    "no APPROX POSITION XYZ in the header; give gnss.base_position_ecef in "
                    "dataset.yaml");
  }
  return p;
}

// The single-receiver scheme's local origin: the rover's first single point position within its
// first 100 epochs (the header's approximate position may be absent or kilometres off).
Eigen::Vector3d roverStart(const DatasetDescription& d, const std::vector<NavData>& navs) {
  const BroadcastOrbits orbits(mergeNav(navs));
  RinexObsReader reader(d.pathOf(d.rover_obs));
  ObsEpoch e;
  double t_first = NAN;
  int covered = 0;
  for (int k = 0; k < 100 && reader.next(e); ++k) {
    if (std::isnan(t_first)) t_first = e.t;
    covered += std::any_of(e.sats.begin(), e.sats.end(),
                           [&](const SatObs& s) { return orbits.select(s.sat, e.t) != nullptr; });
    const SppSolution spp = solveSpp(e, orbits, SppOptions{});
    if (spp.valid) return spp.p_e;
  }
  if (covered == 0 && !d.nav.empty()) {
    throw DataError(d.pathOf(d.nav.front()), 0,
                    "no ephemeris covers the rover's observations at t=" + timeText(t_first) +
                        " (" + d.pathOf(d.rover_obs) + ")");
  }
  throw DataError(d.pathOf(d.rover_obs), 0,
                  "no single point position in the first 100 epochs (too few satellites with "
                  "code and an ephemeris)");
}

// The dataset's unusable conditions (dataset_diagnosis), its files read again (only after a
// failed initialization).
std::vector<std::string> diagnoseFolder(const DatasetDescription& d, double max_base_offset) {
  const ObsData rover = readRinexObs(d.pathOf(d.rover_obs));
  const ObsData base = readRinexObs(d.pathOf(d.base_obs));
  std::vector<NavData> navs;
  for (const std::string& n : d.nav) navs.push_back(readRinexNav(d.pathOf(n)));
  const NavData nav = mergeNav(navs);
  const std::vector<OdomSample> odom = readOdomCsv(d.pathOf(d.odom));
  return diagnoseDataset({rover, base, nav, odom, d.pathOf(d.rover_obs), d.pathOf(d.base_obs),
                          d.pathOf(d.nav.front()), d.pathOf(d.odom), max_base_offset});
}

}  // namespace

CalibrationRun replayFolder(const std::string& folder, const ReplayJob& job, RunSink* sink) {
  return replayFolder(openDatasetFolder(folder), job, sink);
}

CalibrationRun replayFolder(const DatasetFolder& data, const ReplayJob& job, RunSink* sink) {
  const auto t0 = std::chrono::steady_clock::now();
  const DatasetDescription& d = data.description;
  // Without raw GNSS the LC scheme's solutions are the only GNSS (an imported bag's gnss.pos).
  const bool raw = !d.rover_obs.empty() || job.positions.empty();
  const bool single = job.options.single_receiver;  // rover only, no base
  if (single && d.rover_obs.empty())
    throw DataError(d.pathOf("dataset.yaml"), 0, "--gnss single needs files.rover_obs");
  if (raw && !single) requireRawGnss(d);
  auto need = [&](const std::string& name) {
    const std::string p = d.pathOf(name);
    if (!std::filesystem::exists(p)) throw DataError(p, 0, "file missing");
    return p;
  };
  auto imu = std::make_shared<ImuLogReader>(need(d.imu));
  auto odom = std::make_shared<OdomLogReader>(need(d.odom));
  std::shared_ptr<RinexObsReader> rover, base;
  if (raw) {
    rover = std::make_shared<RinexObsReader>(need(d.rover_obs));
    if (!single) base = std::make_shared<RinexObsReader>(need(d.base_obs));
  }
  std::vector<PositionFix> positions;  // a solution file is small: read whole
  std::vector<std::string> pos_warnings;
  if (!job.positions.empty()) {
    positions = readPosFile(job.positions, &pos_warnings);
    if (positions.empty()) throw DataError(job.positions, 0, "no position solutions");
  }
  std::vector<NavData> navs;
  for (const std::string& n : d.nav) navs.push_back(readRinexNav(need(n)));
  // The local frame's origin: the base, else the first solution.
  const Eigen::Vector3d origin_e = single ? roverStart(d, navs)
                                   : raw  ? basePosition(d, base->header())
                                          : positions.front().p_e;
  std::unique_ptr<Calibrator> cal =
      makeCalibrator(job.estimator, d, origin_e, job.options, job.fgo_options, sink);
  if (!navs.empty()) cal->addNavigation(mergeNav(navs));
  Calibrator& c = *cal;
  std::vector<Stream> streams;
  streams.push_back(readerStream<ImuLogReader, ImuSample>(
      imu, [&c](const ImuSample& s) { c.addImu(s); }, d.time_offsets.imu));
  streams.push_back(readerStream<OdomLogReader, OdomSample>(
      odom, [&c](const OdomSample& s) { c.addOdometer(s); }, d.time_offsets.odometer));
  if (raw) {
    streams.push_back(
        readerStream<RinexObsReader, ObsEpoch>(rover, [&c](const ObsEpoch& e) { c.addRover(e); }));
    if (base) {
      streams.push_back(
          readerStream<RinexObsReader, ObsEpoch>(base, [&c](const ObsEpoch& e) { c.addBase(e); }));
    }
  }
  if (!positions.empty()) {
    streams.push_back(vectorStream<PositionFix>(
        positions, [&c](const PositionFix& p) { c.addPosition(p); }, d.time_offsets.positions));
  }
  merge(streams, job.stop);
  if (streams[0].count < 2) throw DataError(d.pathOf(d.imu), 0, "fewer than two IMU samples");
  if (streams[1].count == 0) throw DataError(d.pathOf(d.odom), 0, "no odometer samples");
  if (raw && streams[2].count == 0) throw DataError(d.pathOf(d.rover_obs), 0, "no epochs");
  if (base && streams[3].count == 0) throw DataError(d.pathOf(d.base_obs), 0, "no epochs");
  try {
    c.finish();
  } catch (const std::runtime_error& e) {
    // A failed initialization says which condition of the data it met, when one is found.
    const std::vector<std::string> why = raw && !single
                                             ? diagnoseFolder(d, job.options.max_base_offset)
                                             : std::vector<std::string>{};
    if (why.empty()) throw;
    std::string text = std::string(e.what()) + "; the dataset:";
    for (const std::string& w : why) text += " " + w + ";";
    text.pop_back();
    throw std::runtime_error(text);
  }
  CalibrationRun run = c.run();
  // Recoverable damage the readers dropped leads the run's warnings.
  std::vector<std::string> damage = imu->warnings();
  std::vector<std::vector<std::string>> more{odom->warnings()};
  if (raw) {
    more.push_back(rover->warnings());
    if (base) more.push_back(base->warnings());
  }
  more.push_back(pos_warnings);
  for (const auto& m : more) damage.insert(damage.end(), m.begin(), m.end());
  run.warnings.insert(run.warnings.begin(), damage.begin(), damage.end());
  if (run.data_duration_s <= 0.0) {
    throw DataError(d.pathOf(d.imu), 0,
                    raw ? "the IMU log and the rover observations do not overlap"
                        : "the IMU log and the position solutions do not overlap");
  }
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  run.load_time_s = std::max(0.0, total - run.wall_time_s);
  run.options = job.options_in_effect;
  return run;
}

CalibrationRun replayInputs(const CalibrationInputs& in, const ReplayJob& job, RunSink* sink) {
  std::unique_ptr<Calibrator> cal =
      makeCalibrator(job.estimator, in.description, in.base_e, job.options, job.fgo_options, sink);
  cal->addNavigation(in.nav);
  Calibrator& c = *cal;
  // The inputs' times have dataset.yaml's time_offsets applied (loadCalibrationInputs); the
  // calibrator applies them itself, so it gets the times as the logs wrote them.
  const TimeOffsets& off = in.description.time_offsets;
  std::vector<Stream> streams;
  streams.push_back(vectorStream<ImuSample>(in.imu, [&c, &off](ImuSample s) {
    s.t -= off.imu;
    c.addImu(s);
  }));
  streams.push_back(vectorStream<OdomSample>(in.odom, [&c, &off](OdomSample s) {
    s.t -= off.odometer;
    c.addOdometer(s);
  }));
  // Without raw GNSS the calibrator makes the epochs from the positions; inputs loaded with a
  // .pos carry the same epochs (loadCalibrationInputs), which would arrive twice.
  if (!in.description.rover_obs.empty()) {
    streams.push_back(
        vectorStream<ObsEpoch>(in.rover.epochs, [&c](const ObsEpoch& e) { c.addRover(e); }));
  }
  streams.push_back(
      vectorStream<ObsEpoch>(in.base.epochs, [&c](const ObsEpoch& e) { c.addBase(e); }));
  streams.push_back(vectorStream<PositionFix>(in.positions, [&c, &off](PositionFix p) {
    p.t -= off.positions;
    c.addPosition(p);
  }));
  merge(streams, job.stop);
  c.finish();
  return c.run();
}

}  // namespace giocal
