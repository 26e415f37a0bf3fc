// UbxStream: the frames of a u-blox UBX binary log (sync 0xB5 0x62, class, id, length, payload,
// 8-bit Fletcher checksum; u-blox interface description, "UBX protocol"), with the damage counted.
#pragma once

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace giocal::import {

struct UbxFrame {
  uint8_t cls = 0;
  uint8_t id = 0;
  std::vector<uint8_t> payload;
  long long offset = 0;  // byte offset of the sync characters in the file
};

struct UbxStreamCounts {
  long long frames = 0;
  long long bad_checksums = 0;  // frames whose checksum failed (skipped, the search resumes)
  long long skipped_bytes = 0;  // bytes outside any valid frame (NMEA, RTCM, damage)
  bool truncated_end = false;   // the file ends inside a frame
  long long first_bad_offset = -1;
};

class UbxStream {
 public:
  /// Throws std::runtime_error "<path>: cannot open file" when it cannot be read.
  explicit UbxStream(const std::string& path);
  /// The next frame with a valid checksum; false at the end of the file.
  bool next(UbxFrame& frame);
  const UbxStreamCounts& counts() const { return counts_; }
  const std::string& path() const { return path_; }

 private:
  bool fill(std::size_t need);  // at least `need` bytes buffered from pos_; false at the end
  std::string path_;
  std::ifstream in_;
  std::vector<uint8_t> buf_;
  std::size_t pos_ = 0;
  long long buf_offset_ = 0;  // file offset of buf_[0]
  UbxStreamCounts counts_;
};

/// A frame's bytes (sync to checksum) for a class, id and payload; the writer tests and fuzzing
/// use.
std::vector<uint8_t> ubxFrameBytes(uint8_t cls, uint8_t id, const std::vector<uint8_t>& payload);

}  // namespace giocal::import
