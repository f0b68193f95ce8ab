#include "nodes/activity_record.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "util/input_error.h"
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

void ActivityRecord::write(const std::string& path) const {
  // Written beside the file and renamed into place: never a half-written record.
  const std::string partial = path + ".partial";
  std::ofstream out(partial, std::ios::binary | std::ios::trunc);
  out.write(kHeader, sizeof kHeader - 1);
  for (const Stream& s : streams_) {
    const std::int32_t node = s.node;
    const std::uint64_t length = s.bytes.size();
    out.write(reinterpret_cast<const char*>(&node), sizeof node);
    out.write(reinterpret_cast<const char*>(&length), sizeof length);
    out.write(reinterpret_cast<const char*>(s.bytes.data()), std::streamsize(length));
  }
  out.close();
  if (!out || std::rename(partial.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(partial.c_str());
    throw OutputError("NCUBE_RECORD_ACTIVITIES " + path + ": cannot write: " + why);
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
