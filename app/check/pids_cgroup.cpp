#include "app/check/pids_cgroup.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace rasterlab::check {

namespace {

std::string readText(const std::string& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

bool writeText(const std::string& path, const std::string& text) {
    std::ofstream out(path);
    out << text;
    out.flush();
    return bool(out);
}

// Where a child cgroup with a pids controller can be made: cgroup v1's pids hierarchy, else
// our own cgroup v2 when it hands pids to its children.
std::string pidsParent() {
    if (access("/sys/fs/cgroup/pids/cgroup.procs", F_OK) == 0) return "/sys/fs/cgroup/pids";
    std::istringstream lines(readText("/proc/self/cgroup"));
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("0::", 0) != 0) continue;
        for (const char* root : {"/sys/fs/cgroup", "/sys/fs/cgroup/unified"}) {
            const std::string own = root + line.substr(3);
            if (readText(own + "/cgroup.subtree_control").find("pids") != std::string::npos)
                return own;
        }
    }
    return {};
}

}  // namespace

PidsCgroup::PidsCgroup(std::string directory)
    : m_directory(std::move(directory)), m_procs(m_directory + "/cgroup.procs") {}

std::unique_ptr<PidsCgroup> PidsCgroup::make(int maxProcesses, std::string* reason) {
    const std::string parent = pidsParent();
    if (parent.empty()) {
        *reason = "no pids cgroup to make one in";
        return nullptr;
    }
    static std::atomic<int> made{0};
    const std::string directory =
        parent + "/rasterlab-check-" + std::to_string(getpid()) + "-" + std::to_string(made++);
    if (mkdir(directory.c_str(), 0700) != 0) {
        *reason = "cannot make a cgroup in " + parent + ": " + std::strerror(errno);
        return nullptr;
    }
    std::unique_ptr<PidsCgroup> cgroup(new PidsCgroup(directory));
    if (!writeText(directory + "/pids.max", std::to_string(maxProcesses))) {
        *reason = "cannot set pids.max in " + directory;
        return nullptr;  // the destructor removes the folder
    }
    return cgroup;
}

PidsCgroup::~PidsCgroup() {
    // A cgroup is removed once empty; its processes were killed, they may take a moment.
    for (int i = 0; i < 50; ++i) {
        killAll();
        if (rmdir(m_directory.c_str()) == 0 || errno == ENOENT) return;
        usleep(10000);
    }
}

bool PidsCgroup::enter() const {
    const int fd = open(m_procs.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) return false;
    const bool written = write(fd, "0\n", 2) == 2;  // 0: the writing process
    close(fd);
    return written;
}

void PidsCgroup::killAll() const {
    std::istringstream pids(readText(m_procs));
    for (long pid = 0; pids >> pid;)
        if (pid > 0) kill(pid_t(pid), SIGKILL);
}

}  // namespace rasterlab::check
