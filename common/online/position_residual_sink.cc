#include "common/online/position_residual_sink.h"

#include "common/io/text.h"

namespace giocal {

std::string understatedSigmaWarning(const PositionResiduals& r) {
  if (r.fixes < 30 || r.understatedBy() < kUnderstatedSigmaWarning) return "";
  return "the position solutions' horizontal errors are " + fixedText(r.sigma_ratio, 1) +
         " times their stated sigmas and stay alike for about " + fixedText(r.correlation_s, 1) +
         " s (" + fixedText(r.inflation, 0) +
         " fixes count as one): the calibration's sigmas are likely about " +
         fixedText(r.understatedBy(), 0) +
         " times too small; the two estimators may disagree by more than their sigmas "
         "(summary.json: lc_residuals, and sd_supported: the sigmas times that factor)";
}

}  // namespace giocal
