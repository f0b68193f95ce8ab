#include "nodes/activity_record.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "util/input_file.h"

namespace ncube {
namespace {

constexpr char kHeader[] = "ncube-activities 1\n";

template <typename T>
void append(std::vector<unsigned char>& bytes, T value) {
  unsigned char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  bytes.insert(bytes.end(), raw, raw + sizeof(T));
}

}  // namespace

void ActivityRecord::Stream::executed(double flops) {
  bytes.push_back(kExecute);
  append(bytes, flops);
}

void ActivityRecord::Stream::put(int to, std::uint64_t message_bytes) {
  bytes.push_back(kPut);
  append(bytes, std::int32_t(to));
  append(bytes, message_bytes);
}

std::string ActivityRecord::requested_path() {
  const char* path = std::getenv("NCUBE_RECORD_ACTIVITIES");
  return path ? path : "";
}

ActivityRecord::Stream& ActivityRecord::add_node(int node) {
  streams_.emplace_back();
  streams_.back().node = node;
  return streams_.back();
}

void ActivityRecord::write(const std::function<void(std::string_view)>& out) const {
  out(std::string_view(kHeader, sizeof kHeader - 1));
  for (const Stream& s : streams_) {
    const std::int32_t node = s.node;
    const std::uint64_t length = s.bytes.size();
    out(std::string_view(reinterpret_cast<const char*>(&node), sizeof node));
    out(std::string_view(reinterpret_cast<const char*>(&length), sizeof length));
    out(std::string_view(reinterpret_cast<const char*>(s.bytes.data()), length));
  }
}

ActivityRecord ActivityRecord::read(const std::string& path) {
  InputStream in(path, kActivityRecord);
  char header[sizeof kHeader - 1];
  if (!in.read(header, sizeof header) || std::memcmp(header, kHeader, sizeof header) != 0)
    throw std::runtime_error(path + ": not an activity record (no \"ncube-activities 1\" line)");
  ActivityRecord record;
  std::int32_t node = 0;
  while (in.read(reinterpret_cast<char*>(&node), sizeof node)) {
    std::uint64_t length = 0;
    Stream& s = record.add_node(node);
    if (!in.read(reinterpret_cast<char*>(&length), sizeof length))
      throw std::runtime_error(path + ": node " + std::to_string(node) + ": stream length cut off");
    s.bytes.resize(length);
    if (!in.read(reinterpret_cast<char*>(s.bytes.data()), std::streamsize(length)))
      throw std::runtime_error(path + ": node " + std::to_string(node) + ": stream cut off");
  }
  return record;
}

}  // namespace ncube
