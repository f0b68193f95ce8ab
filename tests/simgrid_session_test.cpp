// The SimGrid session: what creating the Engine leaves of the process's signal handling.
#include <gtest/gtest.h>

#include <csignal>

#include "machine/simgrid_session.h"

namespace ncube {
namespace {

void some_handler(int) {}

// SimGrid's own SIGINT handler calls exit(1) inside the handler, which hung Ctrl-C when the
// signal landed inside malloc; the session gives back what SIGINT did before the Engine.
TEST(SimgridSession, SigintIsWhatItWasBeforeTheEngine) {
  struct sigaction mine {};
  mine.sa_handler = some_handler;
  sigemptyset(&mine.sa_mask);
  ASSERT_EQ(sigaction(SIGINT, &mine, nullptr), 0);
  simgrid_engine({});
  struct sigaction now {};
  ASSERT_EQ(sigaction(SIGINT, nullptr, &now), 0);
  EXPECT_EQ(now.sa_handler, &some_handler);
}

// Ignored before (a command a script started in the background) becomes the default: SimGrid's
// handler ended such runs, and whoever stops a sweep's runs relies on it.
TEST(SimgridSession, IgnoredSigintEndsTheRunAsTheDefaultDoes) {
  ASSERT_NE(std::signal(SIGINT, SIG_IGN), SIG_ERR);
  simgrid_engine({});
  struct sigaction now {};
  ASSERT_EQ(sigaction(SIGINT, nullptr, &now), 0);
  EXPECT_EQ(now.sa_handler, SIG_DFL);
}

}  // namespace
}  // namespace ncube
