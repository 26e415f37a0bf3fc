// KalmanWorkspace: storage the Kalman update reuses from one update to the next.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <cstddef>
#include <vector>

namespace giocal {

/// Buffers that only grow. A GNSS update's temporaries (P H^T, S, L^-1 H P: ~130 kB at 72 rows
/// and 75 states) freed after every update left glibc's heap top above its trim threshold, so
/// each update gave the pages back to the kernel and faulted them in again (about a seventh of
/// the EKF's time, measured with glibc's trimming turned off); kept here, they are allocated once.
class KalmanWorkspace {
 public:
  enum Slot : std::size_t { kPHt, kS, kW, kPBefore, kInnovation, kSInnovation, kPHeld, kSlots };
  Eigen::Index gain_rows = 0;  // the rows of the last kalmanGainInto (its W and S factor)
  /// A rows x cols matrix over the slot's buffer; its coefficients are unspecified.
  Eigen::Map<Eigen::MatrixXd> matrix(Slot slot, Eigen::Index rows, Eigen::Index cols) {
    std::vector<double>& b = buffers_[slot];
    const auto size = static_cast<std::size_t>(rows * cols);
    if (b.size() < size) b.resize(size);
    return {b.data(), rows, cols};
  }
  /// `dense` without its exact zeros, as dense.sparseView() gives it, in storage kept from the
  /// last call (reallocated only when the column count or the nonzeros grow).
  const Eigen::SparseMatrix<double>& sparse(const Eigen::MatrixXd& dense) {
    sparse_.resize(dense.rows(), dense.cols());
    Eigen::Index nonzeros = 0;
    for (Eigen::Index j = 0; j < dense.cols(); ++j)
      for (Eigen::Index i = 0; i < dense.rows(); ++i) nonzeros += dense(i, j) != 0.0;
    sparse_.reserve(nonzeros);
    for (Eigen::Index j = 0; j < dense.cols(); ++j) {
      sparse_.startVec(j);
      for (Eigen::Index i = 0; i < dense.rows(); ++i) {
        if (dense(i, j) != 0.0) sparse_.insertBack(i, j) = dense(i, j);
      }
    }
    sparse_.finalize();
    return sparse_;
  }

 private:
  std::array<std::vector<double>, kSlots> buffers_;
  Eigen::SparseMatrix<double> sparse_;
};

}  // namespace giocal
