#include "common/io/progress_line.h"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <utility>

#include "common/io/csv_table.h"
#include "common/io/dataset_description.h"

namespace giocal {
namespace {

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

ProgressLine::ProgressLine(std::string label, double t_begin, double t_end, bool quiet,
                           std::string of_what)
    : label_(std::move(label)),
      of_what_(std::move(of_what)),
      t_begin_(t_begin),
      t_end_(t_end),
      enabled_(!quiet && t_end > t_begin && ::isatty(STDERR_FILENO)),
      started_(now()) {}

void ProgressLine::update(double t) {
  if (!enabled_) return;
  const double wall = now();
  if (shown_ && wall - last_drawn_ < 0.2) return;
  last_drawn_ = wall;
  const double share = std::min(1.0, std::max(0.0, (t - t_begin_) / (t_end_ - t_begin_)));
  const double elapsed = wall - started_;
  char text[200];
  if (share > 0.01) {
    std::snprintf(text, sizeof text, "\r  %s: %3.0f %% %s, %.0f s elapsed, %.0f s left  ",
                  label_.c_str(), 100.0 * share, of_what_.c_str(), elapsed,
                  elapsed * (1.0 - share) / share);
  } else {
    std::snprintf(text, sizeof text, "\r  %s: %3.0f %% %s, %.0f s elapsed  ", label_.c_str(),
                  100.0 * share, of_what_.c_str(), elapsed);
  }
  std::fputs(text, stderr);
  std::fflush(stderr);
  shown_ = true;
}

void ProgressLine::clear() {
  if (!shown_) return;
  std::fputs("\r\033[K", stderr);
  std::fflush(stderr);
  shown_ = false;
}

}  // namespace giocal
