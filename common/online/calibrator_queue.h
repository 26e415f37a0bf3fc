// CalibratorQueue: a thread-safe front of the online Calibrator for a robot. Sensor callbacks on
// any thread only enqueue (a copy under a lock: no estimation runs in them); the estimation runs
// in step(), on the thread the robot chooses, or on a worker thread of the queue's own (start());
// the getters return a snapshot consistent with itself, taken after the step that made the latest
// estimate (and every hundred steps).
#pragma once

#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <variant>

#include "common/online/calibrator.h"

namespace giocal {

class CalibratorQueue {
 public:
  explicit CalibratorQueue(std::unique_ptr<Calibrator> calibrator);
  ~CalibratorQueue();  // stops the worker (what is still queued is not processed)
  CalibratorQueue(const CalibratorQueue&) = delete;
  CalibratorQueue& operator=(const CalibratorQueue&) = delete;

  // Any thread, any interleaving; each returns at once.
  void addImu(const ImuSample& s) { push(s); }
  void addOdometer(const OdomSample& s) { push(s); }
  void addRover(const ObsEpoch& e) { push(Rover{e}); }
  void addBase(const ObsEpoch& e) { push(Base{e}); }
  void addPosition(const PositionFix& p) { push(p); }
  void addEphemeris(const Ephemeris& e) { push(e); }
  void addNavigation(const NavData& nav) { push(nav); }

  /// Hands everything queued to the calibrator, in arrival order, and takes a new snapshot;
  /// returns how many data it handed. One thread at a time (a second caller waits).
  std::size_t step();
  /// Steps on a worker thread whenever data arrive (instead of calling step()).
  void start();
  /// Stops the worker, steps what is left and finishes the calibrator (Calibrator::finish).
  void finish();

  std::optional<CalibrationEstimate> calibration() const;
  std::optional<NavState> navState() const;
  CalibratorHealth health() const;
  /// The calibrator itself, for what the snapshot does not hold; only between steps (after
  /// finish(), or on the thread that calls step()).
  const Calibrator& calibrator() const { return *calibrator_; }

 private:
  struct Rover {
    ObsEpoch epoch;
  };
  struct Base {
    ObsEpoch epoch;
  };
  using Item = std::variant<ImuSample, OdomSample, Rover, Base, PositionFix, Ephemeris, NavData>;
  template <class T>
  void push(T&& item) {
    {
      const std::lock_guard<std::mutex> lock(queue_mutex_);
      queue_.emplace_back(std::forward<T>(item));
    }
    arrived_.notify_one();
  }
  void hand(Item& item);
  void snapshot();

  std::unique_ptr<Calibrator> calibrator_;  // touched only under step_mutex_
  double snapshot_t_ = -1.0;                // the estimate's time at the last snapshot
  long steps_ = 0;
  std::mutex step_mutex_;
  mutable std::mutex queue_mutex_;  // the queue and the worker's stop flag
  std::condition_variable arrived_;
  std::deque<Item> queue_;
  bool stopping_ = false;
  std::thread worker_;
  mutable std::mutex snapshot_mutex_;
  std::optional<CalibrationEstimate> calibration_;
  std::optional<NavState> nav_;
  CalibratorHealth health_;
};

}  // namespace giocal
