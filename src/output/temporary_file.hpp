#pragma once
// Temporary names for files being written, and the sweep that clears those a killed process left.
//
// A temporary lives next to its final file (same file system, so rename(2) can replace it in one step):
//   <final name>.tmp.<host>.<pid>.<serial>      e.g. frame_00012.png.tmp.node7-4026531836.4711.3
// where <host> is the host name and the pid namespace (containers on one host have their own pids).
// (a video's temporary gets its extension appended, because ffmpeg picks the container from it; a frame's does
// not, so that globs like frames/*.png never pick up a frame still being written). Host and pid say who writes it, so a
// later render can tell a dead writer's leftovers (SIGKILL, power loss) from the work in progress of a live
// shard, also when shards on several hosts or in several containers share one folder.

#include <string>
#include <vector>

namespace sl {

// A fresh temporary path for `finalPath`, unique within this process (serial) and across processes (host, pid).
// Anything appended to it (an extension) is still recognised by the sweep.
std::string temporaryPathFor(const std::string& finalPath);

// Removes the temporaries in `folder` written on this host by processes that no longer exist, and returns
// their names. Temporaries of live processes and of other hosts stay. A missing folder has none.
std::vector<std::string> removeStaleTemporaries(const std::string& folder);

}  // namespace sl
