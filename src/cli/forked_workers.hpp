#pragma once
// Work split over forked processes. The parent forks N workers, which start with its memory as it was (copy on
// write: a frame builder already set up, say); each reports back through a pipe of its own in small messages, and
// waits for the parent's go before it writes anything, so the parent can refuse the whole job (a disk too small, a
// renderer that cannot be made) while nothing is written yet.
//
// Why processes and not threads, for frames: llvmpipe rasterises every OpenGL context of a process under one lock
// (its screen's), so renderers on threads of one process take turns at the shading; in processes of their own they
// draw side by side (docs/rendering.md, "Frames drawn by several processes").
//
// A worker never returns into the caller's code: its body's value is its exit status (_exit, so no destructor of the
// parent's objects runs twice and no buffered output is written twice). A worker dies with its parent (SIGKILL), as
// a thread would: its temporaries are then a dead writer's, swept by the next render.

#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <sys/types.h>
#include <vector>

namespace sl {

// The worker's end: messages up, the go down.
class WorkerChannel {
 public:
  WorkerChannel(int up, int down) : up_(up), down_(down) {}
  // One message: a kind (a letter the caller chooses) and a text. Never throws: a parent gone is noticed later.
  void send(char kind, const std::string& text = "") const;
  // Waits for the parent: true to go on, false to stop without writing (the job was refused, the parent is gone,
  // or `cancelled` says so after a signal interrupted the wait).
  bool waitForGo(const std::function<bool()>& cancelled) const;

 private:
  int up_, down_;
};

class ForkedWorkers {
 public:
  struct Message {
    int worker = 0;
    char kind = 0;  // kEnded: the worker has closed its end (it ended, however)
    std::string text;
  };
  static constexpr char kEnded = '\0';

  // Forks `count` workers; worker i runs body(i, channel) and exits with what it returns. Call with no other thread
  // running in the process (a fork copies only the calling thread). Throws std::system_error if a worker cannot be
  // forked (those already forked are refused and waited for: all or none).
  ForkedWorkers(int count, const std::function<int(int worker, const WorkerChannel&)>& body);
  ~ForkedWorkers();  // workers still waiting for the go are told to stop; every worker is waited for
  ForkedWorkers(const ForkedWorkers&) = delete;
  ForkedWorkers& operator=(const ForkedWorkers&) = delete;

  int count() const { return static_cast<int>(workers_.size()); }
  // Every worker may go on (write).
  void go();
  // Every worker waiting for the go stops without it (the job was refused before anything was written).
  void refuse();
  // The next message of any worker, waiting for it, and a kEnded message when a worker closes its end; nullopt once
  // every worker has (so a caller waiting for news from all sees one that ended without any). A SIGINT
  // or SIGTERM ends the wait (its handler runs); once `signalled` says one came, SIGTERM is sent on to the workers
  // (once), so a signal sent to the parent alone stops them too, and the wait goes on until they end.
  std::optional<Message> next(const std::function<bool()>& signalled);
  // Sends `signal` to every worker not yet ended, and SIGCONT after it, so that a stopped worker acts on it.
  void signalAll(int signal) const;
  // Waits for every worker to end; its exit status (128 + the signal for a worker killed by one).
  std::vector<int> exitStatuses();

 private:
  struct Worker {
    pid_t pid = -1;
    int up = -1, down = -1;  // the parent's ends: read messages, write the go
    std::string received;    // bytes read, not yet a whole message
    bool open = true;
    int status = -1;
  };
  std::optional<Message> takeMessage(Worker& worker, int index);
  void stopAll();
  void noticeStops();  // says which workers are stopped (waitpid WUNTRACED), records those that ended
  std::vector<Worker> workers_;
  bool forwarded_ = false;  // a signal the parent got was sent on (once)
  std::deque<int> ended_;   // workers whose end was found closed, not yet told (kEnded)
};

}  // namespace sl
