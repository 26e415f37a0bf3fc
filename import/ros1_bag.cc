// BagSource over a ROS 1 bag, read with rosbag_storage (no ROS installation, no roscore).
#include <ros/serialization.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>

#include <filesystem>
#include <map>
#include <stdexcept>

#include "import/bag_source.h"

namespace giocal::import {

namespace {

class Ros1Bag : public BagSource {
 public:
  explicit Ros1Bag(const std::string& path) : path_(path) {
    try {
      bag_.open(path, rosbag::bagmode::Read);
    } catch (const std::exception& e) {
      throw std::runtime_error(path + ": not a readable ROS 1 bag (" + e.what() + ")");
    }
    rosbag::View view(bag_);
    std::map<std::string, std::size_t> index;
    for (const rosbag::ConnectionInfo* c : view.getConnections()) {
      if (index.count(c->topic)) continue;  // several connections (publishers) of one topic
      index[c->topic] = topics_.size();
      topics_.push_back({c->topic, c->datatype, c->msg_def, 0});
    }
    for (const rosbag::ConnectionInfo* c : view.getConnections()) {
      rosbag::View one(bag_, rosbag::TopicQuery(c->topic));
      topics_[index[c->topic]].messages = static_cast<long long>(one.size());
    }
  }

  const std::string& path() const override { return path_; }
  RosEncoding encoding() const override { return RosEncoding::kRos1; }
  const std::vector<BagTopic>& topics() const override { return topics_; }

  void read(const std::set<std::string>& topics, const Visit& fn) const override {
    std::map<std::string, const BagTopic*> wanted;
    for (const BagTopic& t : topics_) {
      if (topics.count(t.topic)) wanted[t.topic] = &t;
    }
    std::vector<std::string> names;
    for (const auto& [name, t] : wanted) names.push_back(name);
    std::vector<uint8_t> buf;
    try {
      rosbag::View view(bag_, rosbag::TopicQuery(names));
      for (const rosbag::MessageInstance& m : view) {
        buf.resize(m.size());
        ros::serialization::OStream out(buf.data(), static_cast<uint32_t>(buf.size()));
        m.write(out);
        fn(*wanted.at(m.getTopic()), m.getTime().toSec(), buf.data(), buf.size());
      }
    } catch (const rosbag::BagException& e) {
      throw std::runtime_error(path_ + ": " + e.what());
    }
  }

 private:
  std::string path_;
  mutable rosbag::Bag bag_;
  std::vector<BagTopic> topics_;
};

}  // namespace

std::unique_ptr<BagSource> openRos1Bag(const std::string& path) {
  return std::make_unique<Ros1Bag>(path);
}

}  // namespace giocal::import
