#include "import/bit_buffer.h"

#include <stdexcept>
#include <string>

namespace giocal::import {

namespace {

void check(int pos, int len, int size) {
  if (pos < 0 || len < 0 || len > 32 || pos + len > size) {
    throw std::out_of_range("bit field " + std::to_string(pos) + "+" + std::to_string(len) +
                            " outside a buffer of " + std::to_string(size) + " bits");
  }
}

}  // namespace

int32_t twosComplement(uint32_t v, int len) {
  if (len <= 0 || len >= 32) return static_cast<int32_t>(v);
  v &= (1u << len) - 1u;
  const uint32_t sign = 1u << (len - 1);
  return static_cast<int32_t>((v ^ sign)) - static_cast<int32_t>(sign);
}

uint32_t BitBuffer::u(int pos, int len) const {
  check(pos, len, size());
  uint32_t v = 0;
  for (int k = pos; k < pos + len; ++k) {
    v = (v << 1) | ((bytes_[static_cast<std::size_t>(k / 8)] >> (7 - k % 8)) & 1u);
  }
  return v;
}

int32_t BitBuffer::s(int pos, int len) const { return twosComplement(u(pos, len), len); }

uint32_t BitBuffer::u2(int pos1, int len1, int pos2, int len2) const {
  if (len1 + len2 > 32) throw std::out_of_range("split bit field wider than 32 bits");
  return (u(pos1, len1) << len2) | u(pos2, len2);
}

int32_t BitBuffer::s2(int pos1, int len1, int pos2, int len2) const {
  return twosComplement(u2(pos1, len1, pos2, len2), len1 + len2);
}

void BitBuffer::put(int pos, int len, uint32_t value) {
  check(pos, len, size());
  for (int k = 0; k < len; ++k) {
    const int bit = pos + k;
    const uint8_t mask = static_cast<uint8_t>(1u << (7 - bit % 8));
    auto& byte = bytes_[static_cast<std::size_t>(bit / 8)];
    if ((value >> (len - 1 - k)) & 1u) {
      byte = static_cast<uint8_t>(byte | mask);
    } else {
      byte = static_cast<uint8_t>(byte & ~mask);
    }
  }
}

}  // namespace giocal::import
