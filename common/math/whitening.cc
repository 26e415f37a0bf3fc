#include "common/math/whitening.h"

namespace giocal {

Eigen::MatrixXd whitener(const Eigen::MatrixXd& C, const std::string& what) {
  return whitenerOf(C, [&what] { return what; });
}

}  // namespace giocal
