// The simulation plumbing beneath the node programs. A node program says what work it did
// and what it sends; this layer turns counted work into CPU time through the cost model
// (this_actor::execute; the steps charged between two interactions with other nodes run as one call), charges the nCube2's per-message software
// overhead on both sides as CPU time, sends the modeled bytes over the SimGrid network,
// and keeps the per-node statistics and the timeline for the trace.
#pragma once

#include <deque>
#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

#include <simgrid/forward.h>

#include "counts/work_counts.h"
#include "machine/cost_model.h"
#include "machine/platform_config.h"
#include "nodes/activity_record.h"
#include "nodes/messages.h"
#include "nodes/node_role.h"

namespace ncube {

struct NodeStats {
  int node = 0;
  NodeRole role = NodeRole::kRadiosity;
  int rank = 0;      // radiosity processor rank (of its group, for a visibility processor)
  double compute_seconds = 0.0;
  double overhead_seconds = 0.0;  // message software overhead, both directions
  double waiting_seconds = 0.0;   // blocked waiting for a message
  long messages_sent = 0;
  double bytes_sent = 0.0;
  long messages_received = 0;
  double peak_memory_bytes = 0.0;
  double memory_bytes_at_end = 0.0;  // when the program finished (4.1, 4.2: may differ from the start)
  WorkCounts counts;
};

// One slice of a node's timeline (--trace; docs/result-format.md, "The trace"). Recording it
// changes no simulated time: the slices are written down as the charged time runs.
struct TraceEvent {
  int node;
  const char* what;  // "compute", "overhead", "wait"
  double start, end;
  // Where the node's program was: the iteration (the pass of its loop that chooses and shoots
  // a shooter, from 1; 0 before the first) and the patch being shot (-1: not known yet), or
  // the rendering phase (render: iteration and shooter -1).
  int iteration = 0;
  int shooter = -1;
  bool render = false;
  // "overhead" of a send or receive, and "wait": the message's kind, the other node (the
  // receiver of a send; the sender of a receive, or of the message that ended a wait), its
  // modeled bytes (header included) and whether it was sent.
  bool has_message = false;
  MessageKind kind = MessageKind::kStop;
  int peer = -1;
  double bytes = 0.0;
  bool sent = false;
};

// The message kind's name in the trace and the message log: "candidate", "shooter", "stop",
// "points", "answers", "patches", "increments", "elements", "credit", "histogram",
// "selection", "pixels".
const char* message_kind_name(MessageKind kind);

// The mailbox of node `node` ("node-N"), looked up by name once per node and engine: every
// message to a node goes there (NodeRuntime, and bench/simgrid_replay.cpp's replay of them).
simgrid::s4u::Mailbox* node_mailbox(int node);

class NodeRuntime {
 public:
  NodeRuntime(int node, NodeRole role, int rank, const PlatformConfig& platform,
              const CostModel& costs, std::vector<TraceEvent>* trace);

  // Makes this actor the permanent receiver of the node's mailbox, so that messages are
  // delivered as soon as they are sent (the nCube2's DMA into receive buffers).
  void start();
  void finish();
  // From now on, this node's SimGrid activities are also written to `stream`
  // (activity_record.h: what SimGrid alone needs for the run's messages). Changes nothing else.
  void record_activities(ActivityRecord::Stream* stream) { record_ = stream; }
  // Whether the node program reached its end (finish() was called): a node that did not
  // was left blocked when the simulation ended (a deadlock).
  bool finished() const { return finished_; }

  // Charges the counted work as CPU time of this node (simulated time, through the cost
  // model); the host computed it already.
  void charge(const WorkCounts& counts);
  // The same for the rendering phase's work (kept in render_counts()).
  void charge(const RenderCounts& counts);
  const RenderCounts& render_counts() const { return render_counts_; }
  // Sends `message` to node `to`: the sender's overhead, then its modeled bytes (its
  // payload_bytes plus the header) over the e-cube route (asynchronously: the sender goes on).
  void send(int to, std::unique_ptr<Message> message);
  // Waits for the next message of one of the given kinds (messages of other kinds that
  // arrive meanwhile are kept, in order, for a later receive), then pays the receiver's
  // overhead.
  std::unique_ptr<Message> receive(std::initializer_list<MessageKind> kinds);

  // The node's modeled bytes in use: set when the program is placed, changed as it runs
  // (sections 4.1, 4.2: cuts, patches given and received); the peak is reported.
  void set_memory(double bytes) { memory_ = stats_.peak_memory_bytes = bytes; }
  void change_memory(double delta) {
    memory_ += delta;
    if (memory_ > stats_.peak_memory_bytes) stats_.peak_memory_bytes = memory_;
  }
  double memory() const { return memory_; }
  // How many more records of `bytes_each` fit in the node's memory (at most 2^62).
  long records_that_fit(double bytes_each) const;
  double node_memory() const { return platform_.node_memory; }
  // The simulated time, after the CPU time charged so far has run.
  double now();
  // Where the program is, for the trace's events from now on (TraceEvent): the node programs
  // call it as an iteration begins and as its shooter becomes known, the rendering phase once.
  void set_trace_context(int iteration, int shooter) {
    iteration_ = iteration;
    shooter_ = shooter;
  }
  void set_trace_render() { render_ = true; }
  const NodeStats& stats() const { return stats_; }
  const CostModel& costs() const { return costs_; }

 private:
  // Charges `seconds` of CPU time. It runs at the next interaction with the simulated
  // machine (a send, a receive that has to wait, the clock read, the end): consecutive steps
  // of a node's program (receive overhead, work, send overhead) then take one SimGrid
  // activity instead of one each, with the same simulated times up to rounding. Valid
  // because one program runs per node, so nothing else wants the CPU meanwhile.
  void busy(double seconds, const char* what, double& account, const TraceEvent* traced = nullptr);
  // Runs the CPU time charged and not yet run, as one execute().
  void run_charged();

  struct Charged {
    const char* what;
    double seconds;
    TraceEvent event;  // what the trace records of it (when tracing)
  };
  // An event of this node in its current context, for the trace.
  TraceEvent event(const char* what) const;
  std::vector<Charged> charged_;

  const PlatformConfig& platform_;
  const CostModel& costs_;
  std::vector<TraceEvent>* trace_;
  ActivityRecord::Stream* record_ = nullptr;
  NodeStats stats_;
  std::deque<std::unique_ptr<Message>> deferred_;
  RenderCounts render_counts_;
  bool finished_ = false;
  double memory_ = 0.0;
  int iteration_ = 0, shooter_ = -1;  // the trace's context (set_trace_context)
  bool render_ = false;
};

}  // namespace ncube
