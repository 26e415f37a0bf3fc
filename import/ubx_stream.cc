#include "import/ubx_stream.h"

#include <algorithm>
#include <stdexcept>

namespace giocal::import {

namespace {

constexpr uint8_t kSync1 = 0xB5;
constexpr uint8_t kSync2 = 0x62;
// Every length the 16-bit field can hold: a frame of a message giocal does not read is skipped
// whole (its checksum checked), so sync characters inside its payload are never taken for frames.

void checksum(const uint8_t* bytes, std::size_t n, uint8_t& a, uint8_t& b) {
  a = 0;
  b = 0;
  for (std::size_t k = 0; k < n; ++k) {
    a = static_cast<uint8_t>(a + bytes[k]);
    b = static_cast<uint8_t>(b + a);
  }
}

}  // namespace

UbxStream::UbxStream(const std::string& path) : path_(path), in_(path, std::ios::binary) {
  if (!in_) throw std::runtime_error(path + ": cannot open file");
}

bool UbxStream::fill(std::size_t need) {
  if (buf_.size() - pos_ >= need) return true;
  if (pos_ > 0) {
    buf_.erase(buf_.begin(), buf_.begin() + static_cast<std::ptrdiff_t>(pos_));
    buf_offset_ += static_cast<long long>(pos_);
    pos_ = 0;
  }
  while (buf_.size() < need && in_) {
    const std::size_t old = buf_.size();
    const std::size_t chunk = std::max<std::size_t>(need - old, 1 << 16);
    buf_.resize(old + chunk);
    in_.read(reinterpret_cast<char*>(buf_.data() + old), static_cast<std::streamsize>(chunk));
    buf_.resize(old + static_cast<std::size_t>(in_.gcount()));
  }
  return buf_.size() >= need;
}

bool UbxStream::next(UbxFrame& frame) {
  while (true) {
    if (!fill(2)) {
      counts_.skipped_bytes += static_cast<long long>(buf_.size() - pos_);
      pos_ = buf_.size();
      return false;
    }
    if (buf_[pos_] != kSync1 || buf_[pos_ + 1] != kSync2) {
      ++pos_;
      ++counts_.skipped_bytes;
      continue;
    }
    const long long offset = buf_offset_ + static_cast<long long>(pos_);
    if (!fill(6)) {
      counts_.truncated_end = true;
      pos_ = buf_.size();
      return false;
    }
    const std::size_t len = buf_[pos_ + 4] | static_cast<std::size_t>(buf_[pos_ + 5]) << 8;
    if (!fill(8 + len)) {
      counts_.truncated_end = true;
      counts_.skipped_bytes += static_cast<long long>(buf_.size() - pos_);
      pos_ = buf_.size();
      return false;
    }
    uint8_t a = 0, b = 0;
    checksum(&buf_[pos_ + 2], 4 + len, a, b);
    if (a != buf_[pos_ + 6 + len] || b != buf_[pos_ + 7 + len]) {
      ++counts_.bad_checksums;
      if (counts_.first_bad_offset < 0) counts_.first_bad_offset = offset;
      ++pos_;
      ++counts_.skipped_bytes;
      continue;
    }
    frame.cls = buf_[pos_ + 2];
    frame.id = buf_[pos_ + 3];
    frame.payload.assign(buf_.begin() + static_cast<std::ptrdiff_t>(pos_ + 6),
                         buf_.begin() + static_cast<std::ptrdiff_t>(pos_ + 6 + len));
    frame.offset = offset;
    pos_ += 8 + len;
    ++counts_.frames;
    return true;
  }
}

std::vector<uint8_t> ubxFrameBytes(uint8_t cls, uint8_t id, const std::vector<uint8_t>& payload) {
  std::vector<uint8_t> out(8 + payload.size());
  out[0] = kSync1;
  out[1] = kSync2;
  out[2] = cls;
  out[3] = id;
  out[4] = static_cast<uint8_t>(payload.size() & 0xFF);
  out[5] = static_cast<uint8_t>(payload.size() >> 8);
  std::copy(payload.begin(), payload.end(), out.begin() + 6);
  out.resize(6 + payload.size());
  uint8_t a = 0, b = 0;
  checksum(out.data() + 2, out.size() - 2, a, b);
  out.push_back(a);
  out.push_back(b);
  return out;
}

}  // namespace giocal::import
