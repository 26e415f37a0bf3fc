#include "common/online/calibrator_queue.h"

#include <type_traits>
#include <utility>

namespace giocal {

namespace {
constexpr long kSnapshotEvery = 100;  // steps between snapshots without a new estimate
}  // namespace

CalibratorQueue::CalibratorQueue(std::unique_ptr<Calibrator> calibrator)
    : calibrator_(std::move(calibrator)) {
  snapshot();
}

CalibratorQueue::~CalibratorQueue() {
  {
    const std::lock_guard<std::mutex> lock(queue_mutex_);
    stopping_ = true;
  }
  arrived_.notify_all();
  if (worker_.joinable()) worker_.join();
}

void CalibratorQueue::hand(Item& item) {
  std::visit(
      [this](auto& x) {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, ImuSample>) calibrator_->addImu(x);
        if constexpr (std::is_same_v<T, OdomSample>) calibrator_->addOdometer(x);
        if constexpr (std::is_same_v<T, Rover>) calibrator_->addRover(x.epoch);
        if constexpr (std::is_same_v<T, Base>) calibrator_->addBase(x.epoch);
        if constexpr (std::is_same_v<T, PositionFix>) calibrator_->addPosition(x);
        if constexpr (std::is_same_v<T, Ephemeris>) calibrator_->addEphemeris(x);
        if constexpr (std::is_same_v<T, NavData>) calibrator_->addNavigation(x);
      },
      item);
}

void CalibratorQueue::snapshot() {
  auto calibration = calibrator_->calibration();
  auto nav = calibrator_->navState();
  CalibratorHealth health = calibrator_->health();
  const std::lock_guard<std::mutex> lock(snapshot_mutex_);
  calibration_ = std::move(calibration);
  nav_ = std::move(nav);
  health_ = std::move(health);
}

std::size_t CalibratorQueue::step() {
  const std::lock_guard<std::mutex> stepping(step_mutex_);
  std::deque<Item> batch;
  {
    const std::lock_guard<std::mutex> lock(queue_mutex_);
    batch.swap(queue_);
  }
  for (Item& item : batch) hand(item);
  // A new snapshot with each new estimate (a GNSS epoch) and every kSnapshotEvery steps: the
  // health's counters are a map of names, too dear to copy at every IMU sample.
  const auto latest = calibrator_->calibration();
  const double t = latest ? latest->t : -1.0;
  if (!batch.empty() && (t != snapshot_t_ || ++steps_ % kSnapshotEvery == 0)) {
    snapshot_t_ = t;
    snapshot();
  }
  return batch.size();
}

void CalibratorQueue::start() {
  if (worker_.joinable()) return;
  worker_ = std::thread([this] {
    while (true) {
      {
        std::unique_lock<std::mutex> lock(queue_mutex_);
        arrived_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
        if (stopping_) return;
      }
      step();
    }
  });
}

void CalibratorQueue::finish() {
  {
    const std::lock_guard<std::mutex> lock(queue_mutex_);
    stopping_ = true;
  }
  arrived_.notify_all();
  if (worker_.joinable()) worker_.join();
  step();
  const std::lock_guard<std::mutex> stepping(step_mutex_);
  calibrator_->finish();
  snapshot();
}

std::optional<CalibrationEstimate> CalibratorQueue::calibration() const {
  const std::lock_guard<std::mutex> lock(snapshot_mutex_);
  return calibration_;
}

std::optional<NavState> CalibratorQueue::navState() const {
  const std::lock_guard<std::mutex> lock(snapshot_mutex_);
  return nav_;
}

CalibratorHealth CalibratorQueue::health() const {
  const std::lock_guard<std::mutex> lock(snapshot_mutex_);
  return health_;
}

}  // namespace giocal
