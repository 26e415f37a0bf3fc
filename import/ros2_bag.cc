// BagSource over a rosbag2 sqlite3 database (ROS 2; rosbag2_storage_default_plugins' schema:
// topics, messages and, from Iron on, message_definitions), read with Debian's sqlite3.
#include <sqlite3.h>

#include <filesystem>
#include <map>
#include <stdexcept>

#include "import/bag_source.h"

namespace giocal::import {

namespace {

class Statement {
 public:
  Statement(sqlite3* db, const std::string& sql, const std::string& path) {
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &stmt_, nullptr) != SQLITE_OK) {
      throw std::runtime_error(path + ": not a rosbag2 database (" + sqlite3_errmsg(db) + ")");
    }
  }
  ~Statement() { sqlite3_finalize(stmt_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  bool step() { return sqlite3_step(stmt_) == SQLITE_ROW; }
  std::string text(int col) const {
    const auto* p = sqlite3_column_text(stmt_, col);
    return p ? reinterpret_cast<const char*>(p) : "";
  }
  long long integer(int col) const { return sqlite3_column_int64(stmt_, col); }
  const uint8_t* blob(int col, std::size_t& size) const {
    size = static_cast<std::size_t>(sqlite3_column_bytes(stmt_, col));
    return static_cast<const uint8_t*>(sqlite3_column_blob(stmt_, col));
  }

 private:
  sqlite3_stmt* stmt_ = nullptr;
};

std::string databaseOf(const std::string& path) {
  if (!std::filesystem::is_directory(path)) return path;
  for (const auto& e : std::filesystem::directory_iterator(path)) {
    if (e.path().extension() == ".db3") return e.path().string();
  }
  throw std::runtime_error(path + ": a folder without a rosbag2 .db3 file");
}

class Ros2Bag : public BagSource {
 public:
  explicit Ros2Bag(const std::string& path) : path_(databaseOf(path)) {
    if (sqlite3_open_v2(path_.c_str(), &db_, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) {
      const std::string why = db_ ? sqlite3_errmsg(db_) : "out of memory";
      sqlite3_close(db_);
      throw std::runtime_error(path_ + ": cannot open (" + why + ")");
    }
    try {
      std::map<std::string, std::string> definitions;
      if (hasTable("message_definitions")) {
        Statement d(
            db_, "SELECT topic_type, encoding, encoded_message_definition FROM message_definitions",
            path_);
        while (d.step()) {
          if (d.text(1) == "ros2msg") definitions[d.text(0)] = d.text(2);
        }
      }
      Statement t(db_, "SELECT id, name, type, serialization_format FROM topics ORDER BY id",
                  path_);
      while (t.step()) {
        if (t.text(3) != "cdr") continue;  // other serializations are not read
        ids_[t.integer(0)] = topics_.size();
        topics_.push_back({t.text(1), t.text(2), definitions[t.text(2)], 0});
      }
      Statement c(db_, "SELECT topic_id, COUNT(*) FROM messages GROUP BY topic_id", path_);
      while (c.step()) {
        const auto it = ids_.find(c.integer(0));
        if (it != ids_.end()) topics_[it->second].messages = c.integer(1);
      }
    } catch (...) {
      sqlite3_close(db_);
      throw;
    }
  }
  ~Ros2Bag() override { sqlite3_close(db_); }

  const std::string& path() const override { return path_; }
  RosEncoding encoding() const override { return RosEncoding::kCdr; }
  const std::vector<BagTopic>& topics() const override { return topics_; }

  void read(const std::set<std::string>& topics, const Visit& fn) const override {
    Statement m(db_, "SELECT topic_id, timestamp, data FROM messages ORDER BY timestamp, id",
                path_);
    while (m.step()) {
      const auto it = ids_.find(m.integer(0));
      if (it == ids_.end() || !topics.count(topics_[it->second].topic)) continue;
      std::size_t size = 0;
      const uint8_t* data = m.blob(2, size);
      fn(topics_[it->second], 1e-9 * static_cast<double>(m.integer(1)), data, size);
    }
  }

 private:
  bool hasTable(const std::string& name) const {
    Statement s(db_, "SELECT name FROM sqlite_master WHERE type='table' AND name='" + name + "'",
                path_);
    return s.step();
  }

  std::string path_;
  sqlite3* db_ = nullptr;
  std::vector<BagTopic> topics_;
  std::map<long long, std::size_t> ids_;
};

}  // namespace

std::unique_ptr<BagSource> openRos2Bag(const std::string& path) {
  return std::make_unique<Ros2Bag>(path);
}

}  // namespace giocal::import
