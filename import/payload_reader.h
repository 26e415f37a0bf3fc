// PayloadReader: little-endian fields of a UBX payload by byte offset (u-blox types U1, I1, U2,
// U4, R4, R8), refusing to read past the payload.
#pragma once

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace giocal::import {

class PayloadReader {
 public:
  explicit PayloadReader(const std::vector<uint8_t>& payload) : p_(payload) {}

  std::size_t size() const { return p_.size(); }
  uint8_t u1(std::size_t off) const { return p_[at(off, 1)]; }
  int8_t i1(std::size_t off) const { return static_cast<int8_t>(u1(off)); }
  uint16_t u2(std::size_t off) const {
    const std::size_t k = at(off, 2);
    return static_cast<uint16_t>(p_[k] | p_[k + 1] << 8);
  }
  uint32_t u4(std::size_t off) const {
    const std::size_t k = at(off, 4);
    return static_cast<uint32_t>(p_[k]) | static_cast<uint32_t>(p_[k + 1]) << 8 |
           static_cast<uint32_t>(p_[k + 2]) << 16 | static_cast<uint32_t>(p_[k + 3]) << 24;
  }
  float r4(std::size_t off) const {
    const uint32_t bits = u4(off);
    float v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }
  double r8(std::size_t off) const {
    const uint64_t bits = static_cast<uint64_t>(u4(off)) | static_cast<uint64_t>(u4(off + 4)) << 32;
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }

 private:
  std::size_t at(std::size_t off, std::size_t n) const {
    if (off + n > p_.size()) {
      throw std::out_of_range("field at byte " + std::to_string(off) + " past a payload of " +
                              std::to_string(p_.size()) + " bytes");
    }
    return off;
  }
  const std::vector<uint8_t>& p_;
};

}  // namespace giocal::import
