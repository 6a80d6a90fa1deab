// Work split over forked processes (ForkedWorkers): messages arrive whole and from the right worker, whatever their
// length; exit statuses (and signals) come back; a job refused before the go stops every worker without it writing;
// a SIGTERM sent to the parent alone reaches the workers.

#include <gtest/gtest.h>

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "cli/forked_workers.hpp"

namespace sl {
namespace {

TEST(ForkedWorkers, MessagesArriveWholeFromTheirWorkerAndExitStatusesComeBack) {
  const std::string longText(100000, 'x');  // more than a pipe holds at once: read in pieces, put together again
  ForkedWorkers workers(3, [&](int worker, const WorkerChannel& channel) {
    if (!channel.waitForGo([] { return false; })) return 99;
    for (int k = 0; k < 50; ++k) channel.send('d', std::to_string(worker) + ":" + std::to_string(k));
    channel.send('t', longText + std::to_string(worker));
    return 10 + worker;
  });
  ASSERT_EQ(workers.count(), 3);
  workers.go();
  std::map<int, std::vector<std::string>> drawn;
  std::map<int, std::string> texts;
  while (const auto message = workers.next([] { return false; })) {
    if (message->kind == 'd') drawn[message->worker].push_back(message->text);
    if (message->kind == 't') texts[message->worker] = message->text;
  }
  for (int worker = 0; worker < 3; ++worker) {
    ASSERT_EQ(drawn[worker].size(), 50u) << worker;
    for (int k = 0; k < 50; ++k) EXPECT_EQ(drawn[worker][k], std::to_string(worker) + ":" + std::to_string(k));
    EXPECT_EQ(texts[worker], longText + std::to_string(worker));
  }
  EXPECT_EQ(workers.exitStatuses(), (std::vector<int>{10, 11, 12}));
}

TEST(ForkedWorkers, AJobRefusedBeforeTheGoStopsEveryWorkerWithoutGoingOn) {
  ForkedWorkers workers(2, [](int, const WorkerChannel& channel) {
    channel.send('r');
    return channel.waitForGo([] { return false; }) ? 1 : 0;  // 1: it went on
  });
  int ready = 0;
  while (ready < 2) ready += workers.next([] { return false; })->kind == 'r';
  workers.refuse();
  EXPECT_EQ(workers.exitStatuses(), (std::vector<int>{0, 0}));
}

// A worker that ends before it is ready (a crash, a signal) is told to the parent, which would otherwise wait for
// ever for its news while another worker waits for the go.
TEST(ForkedWorkers, AWorkerEndingBeforeItIsReadyIsToldToTheParent) {
  ForkedWorkers workers(2, [](int worker, const WorkerChannel& channel) {
    if (worker == 1) return 5;  // ends at once, without a word
    channel.send('r');
    return channel.waitForGo([] { return false; }) ? 1 : 0;
  });
  std::vector<int> ended;
  int ready = 0;
  while (ended.empty()) {
    const auto message = workers.next([] { return false; });
    ASSERT_TRUE(message.has_value());
    if (message->kind == ForkedWorkers::kEnded) ended.push_back(message->worker);
    ready += message->kind == 'r';
  }
  EXPECT_EQ(ended, std::vector<int>{1});
  workers.refuse();
  EXPECT_EQ(workers.exitStatuses(), (std::vector<int>{0, 5}));
}

std::atomic<bool> gTerminated{false};
extern "C" void onTerminate(int) { gTerminated = true; }

TEST(ForkedWorkers, ASigtermToTheParentAloneReachesTheWorkers) {
  struct sigaction handler = {}, previous = {};
  handler.sa_handler = onTerminate;
  sigemptyset(&handler.sa_mask);
  ::sigaction(SIGTERM, &handler, &previous);
  gTerminated = false;
  std::vector<int> statuses;
  {
    ForkedWorkers workers(2, [](int, const WorkerChannel& channel) {
      ::signal(SIGTERM, SIG_DFL);  // a worker that ignored it would wait for the go for ever
      channel.send('r');
      channel.waitForGo([] { return false; });
      return 0;
    });
    int ready = 0;
    while (ready < 2) ready += workers.next([] { return false; })->kind == 'r';
    std::thread sender([] {  // blocks SIGTERM itself, so the signal interrupts the parent's wait, not this thread
      sigset_t terminate;
      sigemptyset(&terminate);
      sigaddset(&terminate, SIGTERM);
      ::pthread_sigmask(SIG_BLOCK, &terminate, nullptr);
      ::kill(::getpid(), SIGTERM);
    });
    while (workers.next([] { return gTerminated.load(); })) {
    }
    sender.join();
    statuses = workers.exitStatuses();
  }
  ::sigaction(SIGTERM, &previous, nullptr);
  EXPECT_TRUE(gTerminated);
  EXPECT_EQ(statuses, (std::vector<int>{128 + SIGTERM, 128 + SIGTERM}));
}

}  // namespace
}  // namespace sl
