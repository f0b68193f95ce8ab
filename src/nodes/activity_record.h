// Every SimGrid activity of a run's node programs, in each node's order: the CPU time run
// (execute, in flops), the messages put (to whom, how many modeled bytes) and the messages
// taken from the node's mailbox. bench/simgrid_replay.cpp replays a record with no node
// program, no radiosity and no visibility: what SimGrid alone needs for the same messages,
// the floor beside a run (docs/performance.md). Recording changes no simulated time.
//
// Recorded when the environment names a file: NCUBE_RECORD_ACTIVITIES=FILE ./simulate ...
// (the radiosity run only, not the rendering phase); the file is an output like --json, under
// the same rule for paths (docs/cli.md, "Output files"). The file is binary, in the host's byte
// order: a text line "ncube-activities 1", then per node, in the order the actors were
// created, its node number (int32), its stream's length (uint64) and the stream.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace ncube {

class ActivityRecord {
 public:
  enum Op : unsigned char { kExecute = 'E', kPut = 'P', kGet = 'G' };

  // One node's activities, in order.
  struct Stream {
    int node = 0;
    std::vector<unsigned char> bytes;

    void executed(double flops);
    void put(int to, std::uint64_t message_bytes);
    void got() { bytes.push_back(kGet); }
  };

  // The environment's file (NCUBE_RECORD_ACTIVITIES), or "" when none is named.
  static std::string requested_path();

  // A new stream for `node`; streams are written in the order they were added.
  Stream& add_node(int node);
  const std::deque<Stream>& streams() const { return streams_; }

  // The record's bytes, piece by piece, in order (simulate hands them to its output file).
  void write(const std::function<void(std::string_view)>& out) const;
  // Reads a record written by write(); throws std::runtime_error naming the file and what
  // is wrong with it.
  static ActivityRecord read(const std::string& path);

 private:
  std::deque<Stream> streams_;  // a deque: the streams stay where they are as nodes are added
};

}  // namespace ncube
