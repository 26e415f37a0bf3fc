// BitBuffer: the big-endian bit string of a navigation message (bit 0 is the most significant
// bit of byte 0), read and written as unsigned and two's-complement fields as the ICDs number them.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

namespace giocal::import {

/// The `len` low bits of `v` read as a two's-complement number (fields that the ICDs split across
/// pages are put together first, then read with this).
int32_t twosComplement(uint32_t v, int len);

/// A field's integer times its ICD scale factor 2^exp2.
inline double scaled(double v, int exp2) { return std::ldexp(v, exp2); }
/// Semicircles to radians with the value of pi that IS-GPS-200 and the Galileo OS SIS ICD define.
constexpr double kIcdPi = 3.1415926535898;

class BitBuffer {
 public:
  explicit BitBuffer(int bits) : bytes_(static_cast<std::size_t>((bits + 7) / 8), 0) {}

  int size() const { return static_cast<int>(bytes_.size() * 8); }
  /// The `len` (<= 32) bits from `pos` as an unsigned number; throws std::out_of_range past the
  /// end.
  uint32_t u(int pos, int len) const;
  /// The same bits as a two's-complement number.
  int32_t s(int pos, int len) const;
  /// A field split in two parts (MSBs first), as the ICDs split numbers across words.
  uint32_t u2(int pos1, int len1, int pos2, int len2) const;
  int32_t s2(int pos1, int len1, int pos2, int len2) const;
  void put(int pos, int len, uint32_t value);

 private:
  std::vector<uint8_t> bytes_;
};

}  // namespace giocal::import
