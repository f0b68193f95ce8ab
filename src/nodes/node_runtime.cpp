#include "nodes/node_runtime.h"

#include "machine/work_kinds.h"

#include <algorithm>

#include <simgrid/s4u/Actor.hpp>
#include <simgrid/s4u/Comm.hpp>
#include <simgrid/s4u/Engine.hpp>
#include <simgrid/s4u/Mailbox.hpp>
#include <xbt/log.h>

#include <vector>

// --log=ncube_messages.thresh:debug shows every message sent and received.
XBT_LOG_NEW_DEFAULT_CATEGORY(ncube_messages, "the messages between the nodes");

namespace ncube {

// Looked up by name once per node and engine (by_name builds a string and searches a map:
// measurable at thousands of messages per iteration). One engine per process.
simgrid::s4u::Mailbox* node_mailbox(int node) {
  static std::vector<simgrid::s4u::Mailbox*> known;
  static const simgrid::s4u::Engine* engine = nullptr;
  if (engine != simgrid::s4u::Engine::get_instance()) {
    engine = simgrid::s4u::Engine::get_instance();
    known.clear();
  }
  if (std::size_t(node) < known.size() && known[std::size_t(node)]) return known[std::size_t(node)];
  // by_name is a simcall: other actors run meanwhile (and may grow `known`).
  simgrid::s4u::Mailbox* mailbox = simgrid::s4u::Mailbox::by_name("node-" + std::to_string(node));
  if (std::size_t(node) >= known.size()) known.resize(std::size_t(node) + 1, nullptr);
  known[std::size_t(node)] = mailbox;
  return mailbox;
}

NodeRuntime::NodeRuntime(int node, NodeRole role, int rank, const PlatformConfig& platform,
                         const CostModel& costs, std::vector<TraceEvent>* trace)
    : platform_(platform), costs_(costs), trace_(trace) {
  stats_.node = node;
  stats_.role = role;
  stats_.rank = rank;
}

void NodeRuntime::start() { node_mailbox(stats_.node)->set_receiver(simgrid::s4u::Actor::self()); }

void NodeRuntime::finish() {
  run_charged();
  node_mailbox(stats_.node)->set_receiver(nullptr);
  finished_ = true;
  stats_.memory_bytes_at_end = memory_;
}

double NodeRuntime::now() {
  run_charged();
  return simgrid::s4u::Engine::get_clock();
}

const char* message_kind_name(MessageKind kind) {
  switch (kind) {
    case MessageKind::kCandidate: return "candidate";
    case MessageKind::kShooter: return "shooter";
    case MessageKind::kStop: return "stop";
    case MessageKind::kPoints: return "points";
    case MessageKind::kAnswers: return "answers";
    case MessageKind::kPatches: return "patches";
    case MessageKind::kIncrements: return "increments";
    case MessageKind::kElements: return "elements";
    case MessageKind::kCredit: return "credit";
    case MessageKind::kHistogram: return "histogram";
    case MessageKind::kSelection: return "selection";
    case MessageKind::kPixels: return "pixels";
  }
  return "unknown";
}

TraceEvent NodeRuntime::event(const char* what) const {
  TraceEvent e{stats_.node, what, 0.0, 0.0};
  e.iteration = render_ ? -1 : iteration_;
  e.shooter = render_ ? -1 : shooter_;
  e.render = render_;
  return e;
}

void NodeRuntime::busy(double seconds, const char* what, double& account, const TraceEvent* traced) {
  if (seconds <= 0.0) return;
  account += seconds;
  charged_.push_back({what, seconds, trace_ ? (traced ? *traced : event(what)) : TraceEvent{}});
}

void NodeRuntime::run_charged() {
  if (charged_.empty()) return;
  double total = 0.0;
  for (const Charged& c : charged_) total += c.seconds;
  double start = simgrid::s4u::Engine::get_clock();
  simgrid::s4u::this_actor::execute(total * platform_.node_speed);
  if (record_) record_->executed(total * platform_.node_speed);
  if (trace_)
    for (const Charged& c : charged_) {
      TraceEvent e = c.event;
      e.start = start;
      e.end = start + c.seconds;
      trace_->push_back(e);
      start += c.seconds;
    }
  charged_.clear();
}

void NodeRuntime::charge(const WorkCounts& counts) {
  stats_.counts += counts;
  busy(compute_seconds(costs_, platform_, counts), "compute", stats_.compute_seconds);
}

void NodeRuntime::charge(const RenderCounts& counts) {
  render_counts_ += counts;
  busy(compute_seconds(costs_, platform_, counts), "compute", stats_.compute_seconds);
}

void NodeRuntime::send(int to, std::unique_ptr<Message> message) {
  const double bytes = payload_bytes(*message, costs_) + costs_.message_header_bytes;
  TraceEvent traced = event("overhead");
  traced.has_message = traced.sent = true;
  traced.kind = message->kind;
  traced.peer = to;
  traced.bytes = bytes;
  busy(platform_.send_overhead, "overhead", stats_.overhead_seconds, &traced);
  run_charged();  // the message leaves once the sender's overhead has run
  message->from = stats_.node;
  ++stats_.messages_sent;
  stats_.bytes_sent += bytes;
  XBT_DEBUG("node %d -> node %d: %s, %.0f bytes", stats_.node, to, message_kind_name(message->kind),
            bytes);
  if (record_) record_->put(to, std::uint64_t(bytes));
  node_mailbox(to)->put_init(message.release(), std::uint64_t(bytes))->detach();
}

std::unique_ptr<Message> NodeRuntime::receive(std::initializer_list<MessageKind> kinds) {
  auto wanted = [&kinds](const Message& m) {
    for (MessageKind k : kinds)
      if (m.kind == k) return true;
    return false;
  };
  std::unique_ptr<Message> message;
  for (auto it = deferred_.begin(); it != deferred_.end(); ++it)
    if (wanted(**it)) {
      message = std::move(*it);
      deferred_.erase(it);
      break;
    }
  // A message already delivered is taken at once; before waiting for one, the charged CPU
  // time runs (it would have run before this receive began).
  simgrid::s4u::Mailbox* mailbox = node_mailbox(stats_.node);
  double wait_start = -1.0;
  while (!message) {
    if (!mailbox->ready()) run_charged();
    const double before = simgrid::s4u::Engine::get_clock();
    std::unique_ptr<Message> arrived = mailbox->get_unique<Message>();
    if (record_) record_->got();
    if (simgrid::s4u::Engine::get_clock() > before && wait_start < 0.0) wait_start = before;
    if (wanted(*arrived))
      message = std::move(arrived);
    else
      deferred_.push_back(std::move(arrived));
  }
  TraceEvent traced = event("overhead");
  if (trace_) {
    traced.has_message = true;
    traced.kind = message->kind;
    traced.peer = message->from;
    traced.bytes = payload_bytes(*message, costs_) + costs_.message_header_bytes;
  }
  if (wait_start >= 0.0) {
    const double end = simgrid::s4u::Engine::get_clock();
    stats_.waiting_seconds += end - wait_start;
    if (trace_) {
      TraceEvent wait = traced;
      wait.what = "wait";
      wait.start = wait_start;
      wait.end = end;
      trace_->push_back(wait);
    }
  }
  ++stats_.messages_received;
  XBT_DEBUG("node %d <- node %d: %s", stats_.node, message->from, message_kind_name(message->kind));
  busy(platform_.receive_overhead, "overhead", stats_.overhead_seconds, &traced);
  return message;
}

long NodeRuntime::records_that_fit(double bytes_each) const {
  const double free_bytes = node_memory() - memory();
  return free_bytes >= 0x1p62 * bytes_each ? long(1) << 62
                                           : long(std::max(0.0, free_bytes) / bytes_each);
}

}  // namespace ncube
