// A pids cgroup of its own for a student's program: the kernel refuses a fork past its
// pids.max whoever runs it. RLIMIT_NPROC does the same for a user, but never for root (a
// teacher's container, CI), where this is the only way to bound the processes.
#pragma once

#include <memory>
#include <string>

namespace rasterlab::check {

class PidsCgroup {
public:
    // A new cgroup under the pids hierarchy (cgroup v1's pids/, or our own cgroup v2 where
    // it offers pids), at most maxProcesses tasks; null, with the reason, where none can be
    // made (no such hierarchy, or no right to write it).
    static std::unique_ptr<PidsCgroup> make(int maxProcesses, std::string* reason);
    ~PidsCgroup();  // kills whatever is still in it, then removes it
    PidsCgroup(const PidsCgroup&) = delete;
    PidsCgroup& operator=(const PidsCgroup&) = delete;

    // For the child between fork and exec: moves the calling process into the cgroup, with
    // system calls only. False when the kernel refused.
    bool enter() const;
    // Kills every process in the cgroup, those that left the program's process group too.
    void killAll() const;

private:
    explicit PidsCgroup(std::string directory);
    std::string m_directory, m_procs;  // the cgroup's folder, and its cgroup.procs file
};

}  // namespace rasterlab::check
