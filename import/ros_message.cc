#include "import/ros_message.h"

#include <cmath>
#include <cstring>
#include <stdexcept>

namespace giocal::import {

namespace {

constexpr int kMaxDepth = 16;  // nesting of message types (a cyclic definition stops here)

}  // namespace

// Reads or writes one message, field by field, in ROS 1 or CDR layout.
class RosCodec {
 public:
  RosCodec(const RosSchema& schema, RosEncoding encoding) : schema_(schema), enc_(encoding) {}

  void read(const uint8_t* data, std::size_t size, RosMessage& msg) {
    in_ = data;
    size_ = size;
    pos_ = 0;
    if (enc_ == RosEncoding::kCdr) {
      need(4, "CDR header");
      if (in_[1] != 0x01)
        throw std::runtime_error("CDR data not little-endian (header " + std::to_string(in_[1]) +
                                 ")");
      base_ = pos_ = 4;
    }
    msg_ = &msg;
    readType(schema_.root(), "", 0);
  }

  std::vector<uint8_t> write(const RosMessage& msg) {
    out_.clear();
    cmsg_ = &msg;
    if (enc_ == RosEncoding::kCdr) {
      out_ = {0x00, 0x01, 0x00, 0x00};
      base_ = 4;
    }
    writeType(schema_.root(), "", 0);
    return out_;
  }

 private:
  void need(std::size_t n, const std::string& what) {
    if (pos_ + n > size_) {
      throw std::runtime_error(schema_.root() + ": message ends inside '" + what + "' (byte " +
                               std::to_string(pos_) + " of " + std::to_string(size_) + ")");
    }
  }
  void align(std::size_t n) {
    if (enc_ == RosEncoding::kCdr && n > 1) pos_ += (n - (pos_ - base_) % n) % n;
  }
  void alignOut(std::size_t n) {
    if (enc_ == RosEncoding::kCdr && n > 1)
      out_.resize(out_.size() + (n - (out_.size() - base_) % n) % n, 0);
  }
  uint32_t u32(const std::string& what) {
    align(4);
    need(4, what);
    uint32_t v;
    std::memcpy(&v, in_ + pos_, 4);
    pos_ += 4;
    return v;
  }
  template <class T>
  double get(const std::string& what) {
    align(sizeof(T));
    need(sizeof(T), what);
    T v;
    std::memcpy(&v, in_ + pos_, sizeof(T));
    pos_ += sizeof(T);
    return static_cast<double>(v);
  }
  double primitive(const std::string& t, const std::string& path) {
    if (t == "bool" || t == "uint8" || t == "char" || t == "byte") return get<uint8_t>(path);
    if (t == "int8") return get<int8_t>(path);
    if (t == "int16") return get<int16_t>(path);
    if (t == "uint16") return get<uint16_t>(path);
    if (t == "int32") return get<int32_t>(path);
    if (t == "uint32") return get<uint32_t>(path);
    if (t == "int64") return get<int64_t>(path);
    if (t == "uint64") return get<uint64_t>(path);
    if (t == "float32") return get<float>(path);
    return get<double>(path);
  }
  void readValue(const std::string& t, const std::string& path, int depth) {
    if (t == "string" || t == "wstring") {
      const uint32_t n = u32(path);
      need(n, path);
      std::string s(reinterpret_cast<const char*>(in_ + pos_), n);
      if (enc_ == RosEncoding::kCdr && !s.empty() && s.back() == '\0') s.pop_back();
      msg_->texts_[path] = s;
      pos_ += n;
    } else if (t == "time" || t == "duration") {
      msg_->numbers_[path + ".sec"] = t == "time" ? get<uint32_t>(path) : get<int32_t>(path);
      msg_->numbers_[path + ".nsec"] = get<int32_t>(path);
    } else if (isRosPrimitive(t)) {
      msg_->numbers_[path] = primitive(t, path);
    } else {
      readType(t, path, depth + 1);
    }
  }
  void readType(const std::string& type, const std::string& prefix, int depth) {
    if (depth > kMaxDepth) throw std::runtime_error(schema_.root() + ": types nested too deeply");
    for (const RosField& f : schema_.fieldsOf(type)) {
      const std::string path = prefix.empty() ? f.name : prefix + "." + f.name;
      if (f.array < 0) {
        readValue(f.type, path, depth);
        continue;
      }
      std::size_t n = static_cast<std::size_t>(f.array);
      if (f.array == 0) {
        n = u32(path);
        // Every element takes at least one byte: a longer count is damage, not an allocation.
        if (n > size_ - pos_)
          throw std::runtime_error(schema_.root() + ": '" + path + "' claims " + std::to_string(n) +
                                   " elements in " + std::to_string(size_ - pos_) + " bytes");
        msg_->lengths_[path] = n;
      }
      for (std::size_t k = 0; k < n; ++k)
        readValue(f.type, path + "[" + std::to_string(k) + "]", depth);
    }
  }

  template <class T>
  void put(double v) {
    alignOut(sizeof(T));
    const T x = static_cast<T>(v);
    const auto* b = reinterpret_cast<const uint8_t*>(&x);
    out_.insert(out_.end(), b, b + sizeof(T));
  }
  double value(const std::string& path) const {
    const auto it = cmsg_->numbers_.find(path);
    return it == cmsg_->numbers_.end() ? 0.0 : it->second;
  }
  void writeValue(const std::string& t, const std::string& path, int depth) {
    if (t == "string" || t == "wstring") {
      const auto it = cmsg_->texts_.find(path);
      std::string s = it == cmsg_->texts_.end() ? "" : it->second;
      if (enc_ == RosEncoding::kCdr) s.push_back('\0');
      put<uint32_t>(static_cast<double>(s.size()));
      out_.insert(out_.end(), s.begin(), s.end());
    } else if (t == "time" || t == "duration") {
      if (t == "time") {
        put<uint32_t>(value(path + ".sec"));
      } else {
        put<int32_t>(value(path + ".sec"));
      }
      put<int32_t>(value(path + ".nsec"));
    } else if (isRosPrimitive(t)) {
      const double v = value(path);
      if (t == "float32")
        put<float>(v);
      else if (t == "float64")
        put<double>(v);
      else if (t == "int8")
        put<int8_t>(v);
      else if (t == "int16")
        put<int16_t>(v);
      else if (t == "uint16")
        put<uint16_t>(v);
      else if (t == "int32")
        put<int32_t>(v);
      else if (t == "uint32")
        put<uint32_t>(v);
      else if (t == "int64")
        put<int64_t>(v);
      else if (t == "uint64")
        put<uint64_t>(v);
      else
        put<uint8_t>(v);
    } else {
      writeType(t, path, depth + 1);
    }
  }
  void writeType(const std::string& type, const std::string& prefix, int depth) {
    if (depth > kMaxDepth) throw std::runtime_error(schema_.root() + ": types nested too deeply");
    for (const RosField& f : schema_.fieldsOf(type)) {
      const std::string path = prefix.empty() ? f.name : prefix + "." + f.name;
      if (f.array < 0) {
        writeValue(f.type, path, depth);
        continue;
      }
      std::size_t n = static_cast<std::size_t>(f.array);
      if (f.array == 0) {
        const auto it = cmsg_->lengths_.find(path);
        n = it == cmsg_->lengths_.end() ? 0 : it->second;
        put<uint32_t>(static_cast<double>(n));
      }
      for (std::size_t k = 0; k < n; ++k)
        writeValue(f.type, path + "[" + std::to_string(k) + "]", depth);
    }
  }

  const RosSchema& schema_;
  RosEncoding enc_;
  const uint8_t* in_ = nullptr;
  std::size_t size_ = 0, pos_ = 0, base_ = 0;
  RosMessage* msg_ = nullptr;
  const RosMessage* cmsg_ = nullptr;
  std::vector<uint8_t> out_;
};

RosMessage RosMessage::decode(const RosSchema& schema, RosEncoding encoding, const uint8_t* data,
                              std::size_t size) {
  RosMessage m;
  RosCodec(schema, encoding).read(data, size, m);
  return m;
}

std::vector<uint8_t> RosMessage::encode(const RosSchema& schema, RosEncoding encoding) const {
  return RosCodec(schema, encoding).write(*this);
}

double RosMessage::number(const std::string& path) const {
  const auto it = numbers_.find(path);
  if (it == numbers_.end()) throw std::runtime_error("message has no field '" + path + "'");
  return it->second;
}

const std::string& RosMessage::text(const std::string& path) const {
  const auto it = texts_.find(path);
  if (it == texts_.end()) throw std::runtime_error("message has no text field '" + path + "'");
  return it->second;
}

std::size_t RosMessage::length(const std::string& path) const {
  const auto it = lengths_.find(path);
  return it == lengths_.end() ? 0 : it->second;
}

double RosMessage::time(const std::string& path) const {
  const double sec = number(path + ".sec");
  const double nsec = has(path + ".nsec") ? number(path + ".nsec") : number(path + ".nanosec");
  return sec + 1e-9 * nsec;
}

}  // namespace giocal::import
