#include "app/check/student_program.h"

#include <QStandardPaths>
#include <QString>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>

#include "app/check/pids_cgroup.h"
#include "pipeline/core/format.h"

extern char** environ;

namespace rasterlab::check {

namespace {

using Clock = std::chrono::steady_clock;

std::string findInPath(const char* program) {
    return QStandardPaths::findExecutable(QString::fromLatin1(program)).toStdString();
}

// The processes this user runs now: RLIMIT_NPROC counts them all, so the limit is on top.
int processesOfThisUser() {
    int count = 0;
    const uid_t uid = getuid();
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator("/proc", ec)) {
        const std::string name = entry.path().filename().string();
        if (name.empty() || !std::all_of(name.begin(), name.end(), ::isdigit)) continue;
        struct stat info {};
        if (stat(entry.path().c_str(), &info) == 0 && info.st_uid == uid) ++count;
    }
    return count;
}

std::string shownText(const std::string& text) {
    std::string s;
    for (char c : text.substr(0, 80)) s += (c >= 0x20 && c < 0x7f) ? c : '?';
    if (text.size() > 80) s += "...";
    return "'" + s + "'";
}

std::string seconds(double s) {
    return rl::formatNumber(s) + " s";
}

// The first byte of a line that is not text: a control character other than tab and CR.
std::optional<std::size_t> binaryByte(const std::string& line) {
    for (std::size_t i = 0; i < line.size(); ++i) {
        const auto c = static_cast<unsigned char>(line[i]);
        if ((c < 0x20 && c != '\t' && c != '\r') || c == 0x7f) return i;
    }
    return std::nullopt;
}

// The lines of the end of a text, the first one dropped when the text was cut inside it.
std::vector<std::string> lastLines(const std::string& text, bool cut) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    if (cut) start = std::min(text.size(), text.find('\n') + 1);
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines.push_back(std::move(line));
        start = end + 1;
    }
    while (!lines.empty() && lines.back().find_first_not_of(" \t") == std::string::npos)
        lines.pop_back();
    return lines;
}

// A line that opens a runtime's report of an error: a Java exception, a Python traceback, a
// "Caused by", an error a runtime prints at its first column ("TypeError: ...").
bool opensReport(const std::string& line) {
    if (line.rfind("Exception in thread", 0) == 0 || line.rfind("Traceback (most recent", 0) == 0 ||
        line.rfind("Caused by:", 0) == 0 || line.rfind("Error occurred during", 0) == 0 ||
        line.rfind("Unhandled exception", 0) == 0)
        return true;
    const std::size_t colon = line.find(": ");
    if (line.empty() || colon == std::string::npos || line[0] == ' ' || line[0] == '\t')
        return false;
    const std::string name = line.substr(0, colon);
    return name.find(' ') == std::string::npos &&
           (name.size() > 5 && (name.compare(name.size() - 5, 5, "Error") == 0 ||
                                (name.size() > 9 &&
                                 name.compare(name.size() - 9, 9, "Exception") == 0)));
}

std::string printable(const std::string& line) {
    std::string s;
    for (char c : line.substr(0, std::size_t(kErrorLineBytes)))
        s += c == '\t' ? ' ' : (c >= 0x20 && c < 0x7f) ? c : '?';
    if (line.size() > std::size_t(kErrorLineBytes)) s += "...";
    return s;
}

// The last kErrorLines lines; where they begin inside a report whose opening line is in the
// last hundred, that line and the next few come first, then "...", then the last lines.
std::vector<std::string> reportLines(const std::vector<std::string>& lines) {
    const std::size_t n = lines.size();
    const std::size_t window = std::size_t(kErrorLines);
    std::vector<std::string> out;
    std::size_t first = n > window ? n - window : 0;
    std::optional<std::size_t> opening;
    for (std::size_t i = n; i-- > (n > 100 ? n - 100 : 0);)
        if (opensReport(lines[i])) {
            opening = i;
            break;
        }
    if (opening && *opening < first) {
        const std::size_t head = 4;
        for (std::size_t i = *opening; i < *opening + head; ++i) out.push_back(printable(lines[i]));
        out.push_back("...");
        first = std::max(first + head + 1, *opening + head);
    }
    for (std::size_t i = first; i < n; ++i) out.push_back(printable(lines[i]));
    return out;
}

// The line of standard error that says most in one line, quoted: the last report's opening
// with its first frame (Java's "Exception in thread ..." and "at Scan.scan(Scan.java:57)"), a
// Python traceback's exception line with the frame it was raised in, or else the last line.
std::string errorHeadline(const std::vector<std::string>& lines) {
    if (lines.empty()) return {};
    std::size_t at = lines.size() - 1;
    bool opening = false;
    for (std::size_t i = lines.size(); i-- > 0;)
        if (opensReport(lines[i]) && lines[i].rfind("Caused by:", 0) != 0) {
            at = i;
            opening = true;
            break;
        }
    const auto trimmed = [](const std::string& line) {
        const std::size_t text = line.find_first_not_of(" \t");
        return text == std::string::npos ? std::string() : line.substr(text);
    };
    if (opening && lines[at].rfind("Traceback (most recent", 0) == 0) {
        // The exception is the first line after the frames that is not indented.
        std::string frame;
        for (std::size_t i = at + 1; i < lines.size(); ++i) {
            if (lines[i].empty() || lines[i][0] == ' ' || lines[i][0] == '\t') {
                if (trimmed(lines[i]).rfind("File ", 0) == 0) frame = trimmed(lines[i]);
                continue;
            }
            return "'" + lines[i] + "'" + (frame.empty() ? std::string() : ", from " + frame);
        }
    }
    std::string line = lines[at];
    if (opening && at + 1 < lines.size()) {
        const std::string next = trimmed(lines[at + 1]);
        if (next.rfind("at ", 0) == 0 || at + 2 == lines.size()) line += " " + next;
    }
    return "'" + line + "'";
}

void setLimit(int resource, rlim_t soft, rlim_t hard) {
    const struct rlimit limit { soft, hard };
    setrlimit(resource, &limit);
}

}  // namespace

// The memory messages of the runtimes a student writes in, and what each means.
std::string memoryHintOf(const std::vector<std::string>& lines, long long limit) {
    static const char* const kMessages[] = {
        "OutOfMemoryError",          "insufficient memory for the Java Runtime",
        "Could not reserve enough",  "compressed class space",
        "JavaScript heap out of memory", "MemoryError",
        "std::bad_alloc",            "Cannot allocate memory",
        "out of memory",             "Out of memory",
        "OutOfMemoryException",
    };
    for (const std::string& line : lines)
        for (const char* m : kMessages)
            if (line.find(m) != std::string::npos)
                return "this is the runtime running out of memory: the program may use " +
                       (limit > 0 ? std::to_string(limit >> 20) + " MiB of data"
                                  : std::string("all the memory there is")) +
                       "; --memory MB gives it more, and a smaller data set or fewer copies "
                       "need less";
    return {};
}

bool sandboxUsable(std::string* reason) {
    static std::once_flag once;
    static bool usable = false;
    static std::string why;
    std::call_once(once, [] {
        const std::string bwrap = findInPath("bwrap");
        if (bwrap.empty()) {
            why = "bubblewrap (bwrap) is not installed";
            return;
        }
        const std::string probe = "'" + bwrap +
                                  "' --ro-bind / / --unshare-net --unshare-pid --die-with-parent "
                                  "-- /bin/true >/dev/null 2>&1";
        usable = std::system(probe.c_str()) == 0;
        if (!usable)
            why =
                "bubblewrap is installed but cannot make a sandbox here (user namespaces refused)";
    });
    if (reason) *reason = why;
    return usable;
}

StudentProgram::StudentProgram(const std::string& command, const std::string& folder,
                               const Limits& limits, bool inTemporaryFolder)
    : m_limits(limits) {
    static std::once_flag ignorePipe;
    std::call_once(ignorePipe, [] { signal(SIGPIPE, SIG_IGN); });
    m_started = Clock::now();
    m_totalDeadline = m_started + std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(limits.totalSeconds));
    m_requestDeadline = m_totalDeadline;
    startProcess(command, folder, inTemporaryFolder);
}

StudentProgram::~StudentProgram() {
    if (m_pid > 0 && !m_reaped) {
        kill(-m_pid, SIGKILL);
        kill(m_pid, SIGKILL);
        reap(true);
    }
    m_cgroup.reset();  // kills what escaped the group, then removes the cgroup
    if (m_stdin >= 0) close(m_stdin);
    if (m_stdout >= 0) close(m_stdout);
    std::error_code ec;
    if (!m_tempFolder.empty()) std::filesystem::remove_all(m_tempFolder, ec);
}

// The command line to exec (bubblewrap's, where it works, around /bin/sh -c), and the
// protections it brings, said in m_protections and m_missing.
std::vector<std::string> StudentProgram::arguments(const std::string& command,
                                                   const std::string& folder) {
    std::string why;
    const bool sandbox = m_limits.sandbox && sandboxUsable(&why);
    std::vector<std::string> args;
    if (sandbox) {
        args = {findInPath("bwrap"),
                "--ro-bind",
                "/",
                "/",
                "--dev",
                "/dev",
                "--proc",
                "/proc",
                "--bind",
                m_tempFolder,
                m_tempFolder,
                "--unshare-net",
                "--unshare-pid",
                "--unshare-ipc",
                "--die-with-parent",
                "--new-session",
                "--chdir",
                folder,
                "--"};
        m_protections.push_back(
            "bubblewrap: no network, the file system read-only but for a temporary folder, "
            "processes of its own");
    } else {
        m_missing.push_back(m_limits.sandbox ? "no sandbox: " + why
                                             : "no sandbox: turned off (--no-sandbox)");
    }
    args.insert(args.end(), {"/bin/sh", "-c", command});
    m_protections.push_back("wall clock: " + seconds(m_limits.requestSeconds) + " per request, " +
                            seconds(m_limits.totalSeconds) + " in all");
    m_protections.push_back("CPU time: " + seconds(m_limits.cpuSeconds));
    (m_limits.memoryBytes > 0 ? m_protections : m_missing)
        .push_back(m_limits.memoryBytes > 0
                       ? "memory: " + std::to_string(m_limits.memoryBytes >> 20) +
                             " MiB of data (heap and private mappings; the address space a "
                             "runtime reserves is free; a JVM is told the limit by "
                             "JAVA_TOOL_OPTIONS)"
                       : std::string("memory: not limited"));
    m_protections.push_back("files written: " + std::to_string(m_limits.fileBytes >> 20) +
                            " MiB each; answers: " + std::to_string(m_limits.answerBytes >> 20) +
                            " MiB, lines " + std::to_string(m_limits.lineBytes >> 10) + " KiB");
    m_protections.push_back("temporary folder: TMPDIR and HOME, removed afterwards");
    return args;
}

void StudentProgram::startProcess(const std::string& command, const std::string& given,
                                  bool inTemporaryFolder) {
    std::string folder = given;
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/rasterlab-check-XXXXXX";
    if (!mkdtemp(pattern.data())) {
        fail(std::string("cannot make a temporary folder: ") + std::strerror(errno));
        return;
    }
    m_tempFolder = pattern;
    const std::string errorFile = m_tempFolder + "/stderr.txt";
    if (inTemporaryFolder) {
        // A copy of the folder to run in, symbolic links left as links (not followed out).
        std::error_code ec;
        folder = m_tempFolder + "/work";
        std::filesystem::copy(
            given, folder,
            std::filesystem::copy_options::recursive | std::filesystem::copy_options::copy_symlinks,
            ec);
        if (ec) {
            fail("cannot copy " + given + " to run in: " + ec.message());
            return;
        }
    }

    std::vector<std::string> args = arguments(command, folder);
    // RLIMIT_NPROC counts this user's processes but never binds root: there a pids cgroup
    // holds the limit, where one can be made.
    const bool root = geteuid() == 0;
    const int nproc = processesOfThisUser() + m_limits.processes;
    const std::string processes = "processes: " + std::to_string(m_limits.processes);
    std::string noCgroup;
    if (root) m_cgroup = PidsCgroup::make(m_limits.processes, &noCgroup);
    if (!root)
        m_protections.push_back(processes + " more than now");
    else if (m_cgroup)
        m_protections.push_back(processes + " (a pids cgroup)");
    else
        m_missing.push_back(processes + " (not enforced: RasterLab runs as root, and " + noCgroup +
                            ")");
    const PidsCgroup* cgroup = m_cgroup.get();

    // Everything the child needs is made before fork: after it only system calls.
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    std::vector<std::string> env;
    for (char** e = environ; *e; ++e)
        if (std::strncmp(*e, "TMPDIR=", 7) != 0 && std::strncmp(*e, "HOME=", 5) != 0)
            env.emplace_back(*e);
    env.push_back("TMPDIR=" + m_tempFolder);
    env.push_back("HOME=" + m_tempFolder);
    // A JVM sizes its heap by the machine's memory (its first commit 1/64 of it): told of the
    // limit, it sizes it by that, and starts on a machine of any size.
    if (m_limits.memoryBytes > 0 && !std::getenv("JAVA_TOOL_OPTIONS"))
        env.push_back("JAVA_TOOL_OPTIONS=-XX:MaxRAM=" + std::to_string(m_limits.memoryBytes >> 20) +
                      "m");
    std::vector<char*> envp;
    for (std::string& e : env) envp.push_back(e.data());
    envp.push_back(nullptr);

    int in[2], out[2];
    if (pipe2(in, O_CLOEXEC) != 0 || pipe2(out, O_CLOEXEC) != 0) {
        fail(std::string("cannot make pipes: ") + std::strerror(errno));
        return;
    }
    const int err = open(errorFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    const pid_t pid = fork();
    if (pid == 0) {
        if (cgroup && !cgroup->enter()) _exit(126);
        setsid();
        dup2(in[0], 0);
        dup2(out[1], 1);
        if (err >= 0) dup2(err, 2);
        const auto cpu = rlim_t(m_limits.cpuSeconds);
        setLimit(RLIMIT_CPU, cpu, cpu + 2);
        if (m_limits.memoryBytes > 0)
            setLimit(RLIMIT_DATA, rlim_t(m_limits.memoryBytes), rlim_t(m_limits.memoryBytes));
        setLimit(RLIMIT_FSIZE, rlim_t(m_limits.fileBytes), rlim_t(m_limits.fileBytes));
        setLimit(RLIMIT_NPROC, rlim_t(nproc), rlim_t(nproc));
        setLimit(RLIMIT_CORE, 0, 0);
        if (chdir(folder.c_str()) != 0) _exit(126);
        execve(argv[0], argv.data(), envp.data());
        _exit(127);
    }
    close(in[0]);
    close(out[1]);
    if (err >= 0) close(err);
    if (pid < 0) {
        close(in[1]);
        close(out[0]);
        fail(std::string("cannot start the program: ") + std::strerror(errno));
        return;
    }
    m_pid = pid;
    m_stdin = in[1];
    m_stdout = out[0];
    fcntl(m_stdin, F_SETFL, fcntl(m_stdin, F_GETFL) | O_NONBLOCK);
    fcntl(m_stdout, F_SETFL, fcntl(m_stdout, F_GETFL) | O_NONBLOCK);
}

bool StudentProgram::fail(const std::string& message) {
    if (!m_error.empty()) return false;
    m_error = message;
    if (m_pid > 0) {
        if (m_talked)  // a program run on a file, not asked over the protocol, reads nothing
            m_error += m_lastLine.empty() ? "; nothing had been read before"
                                          : "; the last line read was " + shownText(m_lastLine);
        const std::string line = errorHeadline(errorLines());
        if (!line.empty()) m_error += "; its standard error says " + line;
    }
    return false;
}

void StudentProgram::beginRequest() {
    m_answerBytes = 0;
    m_answerLines = 0;
    m_requestDeadline =
        std::min(m_totalDeadline,
                 Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                    std::chrono::duration<double>(m_limits.requestSeconds)));
}

int StudentProgram::pollMilliseconds(Clock::time_point deadline) const {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    return int(std::clamp<long long>(left.count(), 0, 100));
}

bool StudentProgram::fillBuffer(Clock::time_point deadline) {
    struct pollfd fd {
        m_stdout, POLLIN, 0
    };
    const int ready = poll(&fd, 1, pollMilliseconds(deadline));
    if (cancelled()) return fail("cancelled");
    if (ready < 0 && errno != EINTR) return fail(std::string("poll: ") + std::strerror(errno));
    if (ready <= 0) return true;  // the caller looks at the clock
    char chunk[65536];
    const ssize_t n = read(m_stdout, chunk, sizeof chunk);
    if (n > 0) {
        m_buffer.append(chunk, std::size_t(n));
        m_answerBytes += n;
        if (m_answerBytes > m_limits.answerBytes)
            return fail("the answer passed " + std::to_string(m_limits.answerBytes >> 20) +
                        " MiB without its 'end' (the output limit)");
        return true;
    }
    if (n < 0 && (errno == EAGAIN || errno == EINTR)) return true;
    reap(false);
    if (!m_reaped) {
        // Output closed: give the program a moment to end, so that its status can be told.
        for (int i = 0; i < 50 && !m_reaped; ++i) {
            usleep(20000);
            reap(false);
        }
    }
    const std::string how = m_reaped ? ending() : "closed its output";
    return fail(
        "the program ended (" + how + ") before it finished answering" +
        (m_buffer.size() == m_bufferStart
             ? std::string()
             : ", in the middle of the line " + shownText(m_buffer.substr(m_bufferStart, 80))));
}

std::optional<std::string> StudentProgram::readLine() {
    if (!m_error.empty()) return std::nullopt;
    if (m_pid <= 0) {
        fail("the program was not started");
        return std::nullopt;
    }
    while (true) {
        const std::size_t end = m_buffer.find('\n', m_bufferStart);
        if (end != std::string::npos) {
            std::string line = m_buffer.substr(m_bufferStart, end - m_bufferStart);
            m_bufferStart = end + 1;
            // Lines are taken from the front; the buffer is cut only now and then, so that a
            // flood of short lines costs no more than reading them.
            if (m_bufferStart > 65536 || m_bufferStart == m_buffer.size()) {
                m_buffer.erase(0, m_bufferStart);
                m_bufferStart = 0;
            }
            if (!line.empty() && line.back() == '\r') line.pop_back();
            if (const auto at = binaryByte(line)) {
                char code[8];
                std::snprintf(code, sizeof code, "0x%02x",
                              unsigned(static_cast<unsigned char>(line[*at])));
                fail("the answer is not text: byte " + std::string(code) + " at column " +
                     std::to_string(*at + 1) + " of its line");
                return std::nullopt;
            }
            if (line.size() > std::size_t(m_limits.lineBytes)) {
                fail("a line of " + std::to_string(line.size()) + " bytes (the limit is " +
                     std::to_string(m_limits.lineBytes) + ")");
                return std::nullopt;
            }
            if (++m_answerLines > m_limits.answerLines) {
                fail("the answer passed " + std::to_string(m_limits.answerLines) +
                     " lines without its 'end' (the output limit)");
                return std::nullopt;
            }
            m_lastLine = line;
            return line;
        }
        if (m_buffer.size() - m_bufferStart > std::size_t(m_limits.lineBytes)) {
            fail("more than " + std::to_string(m_limits.lineBytes) +
                 " bytes without the end of a line ('\\n'); the line begins " +
                 shownText(m_buffer.substr(m_bufferStart, 80)));
            return std::nullopt;
        }
        const Clock::time_point deadline = std::min(m_requestDeadline, m_totalDeadline);
        if (Clock::now() >= deadline) {
            const bool total = m_totalDeadline <= m_requestDeadline;
            fail("no answer within " +
                 seconds(total ? m_limits.totalSeconds : m_limits.requestSeconds) +
                 (total ? " (the limit for the whole run)" : " (the limit per request)") +
                 (m_buffer.size() == m_bufferStart
                      ? std::string()
                      : "; an unfinished line had begun: " +
                            shownText(m_buffer.substr(m_bufferStart, 80))));
            return std::nullopt;
        }
        if (!fillBuffer(deadline)) return std::nullopt;
    }
}

bool StudentProgram::send(const std::string& text) {
    m_talked = true;
    if (!m_error.empty()) return false;
    if (m_pid <= 0) return fail("the program was not started");
    std::size_t sent = 0;
    while (sent < text.size()) {
        const Clock::time_point deadline = std::min(m_requestDeadline, m_totalDeadline);
        if (Clock::now() >= deadline)
            return fail("the program did not read its request within " +
                        seconds(m_limits.requestSeconds));
        // Read what it writes meanwhile, so that neither side waits on a full pipe.
        struct pollfd fds[2] = {{m_stdin, POLLOUT, 0}, {m_stdout, POLLIN, 0}};
        if (poll(fds, 2, pollMilliseconds(deadline)) < 0 && errno != EINTR)
            return fail(std::string("poll: ") + std::strerror(errno));
        if (cancelled()) return fail("cancelled");
        if (fds[1].revents & (POLLIN | POLLHUP)) {
            char chunk[65536];
            const ssize_t n = read(m_stdout, chunk, sizeof chunk);
            if (n > 0) {
                m_buffer.append(chunk, std::size_t(n));
                if (m_buffer.size() > std::size_t(m_limits.answerBytes))
                    return fail("the program wrote more than " +
                                std::to_string(m_limits.answerBytes >> 20) +
                                " MiB while it was being asked");
            }
        }
        if (fds[0].revents & (POLLERR | POLLHUP)) {
            reap(false);
            return fail("the program stopped reading its input (" +
                        (m_reaped ? ending() : std::string("input closed")) + ")");
        }
        if (!(fds[0].revents & POLLOUT)) continue;
        const ssize_t n = write(m_stdin, text.data() + sent, text.size() - sent);
        if (n > 0) {
            sent += std::size_t(n);
        } else if (n < 0 && errno != EAGAIN && errno != EINTR) {
            reap(false);
            return fail("the program stopped reading its input (" +
                        (m_reaped ? ending() : std::string(std::strerror(errno))) + ")");
        }
    }
    return true;
}

bool StudentProgram::waitForExit() {
    if (!m_error.empty()) return false;
    if (m_pid <= 0) return fail("the program was not started");
    if (m_stdin >= 0) {
        close(m_stdin);
        m_stdin = -1;
    }
    long long dropped = 0;
    while (!m_reaped) {
        if (Clock::now() >= m_totalDeadline) {
            kill(-m_pid, SIGKILL);
            kill(m_pid, SIGKILL);
            reap(true);
            return fail("it did not end within " + seconds(m_limits.totalSeconds) +
                        " (the limit for the whole run)");
        }
        struct pollfd fd {
            m_stdout, POLLIN, 0
        };
        if (poll(&fd, 1, pollMilliseconds(m_totalDeadline)) > 0) {
            char chunk[65536];
            const ssize_t n = read(m_stdout, chunk, sizeof chunk);
            if (n > 0) dropped += n;
            if (n == 0) usleep(20000);  // output closed: the program is ending
        }
        if (cancelled()) return fail("cancelled");
        if (dropped > m_limits.answerBytes)
            return fail("it wrote more than " + std::to_string(m_limits.answerBytes >> 20) +
                        " MiB on its standard output (the output limit)");
        reap(false);
    }
    const std::string how = ending();
    if (how != "exit status 0") return fail("it ended with " + how);
    return true;
}

void StudentProgram::stop() {
    if (m_pid <= 0 || m_reaped) return;
    if (m_stdin >= 0) {
        close(m_stdin);
        m_stdin = -1;
    }
    for (int i = 0; i < 25 && !m_reaped; ++i) {  // half a second to end by itself
        reap(false);
        if (!m_reaped) usleep(20000);
    }
    if (!m_reaped) {
        kill(-m_pid, SIGKILL);
        kill(m_pid, SIGKILL);
        reap(true);
    }
}

void StudentProgram::reap(bool wait) {
    if (m_pid <= 0 || m_reaped) return;
    int status = 0;
    const pid_t r = waitpid(m_pid, &status, wait ? 0 : WNOHANG);
    if (r == m_pid) {
        m_reaped = true;
        m_status = status;
        kill(-m_pid, SIGKILL);              // whatever it left behind in its group
        if (m_cgroup) m_cgroup->killAll();  // and out of it
    }
}

std::string StudentProgram::ending() {
    reap(false);
    if (!m_reaped) return {};
    if (WIFEXITED(m_status)) {
        const int code = WEXITSTATUS(m_status);
        if (code == 127) return "exit status 127: the command was not found";
        // A shell, or bubblewrap, reports a child killed by signal s as 128 + s.
        if (code > 128 && code < 128 + 65)
            return "exit status " + std::to_string(code) + ": killed by signal " +
                   std::to_string(code - 128) + " (" + strsignal(code - 128) + ")";
        return "exit status " + std::to_string(code);
    }
    if (WIFSIGNALED(m_status)) {
        const int sig = WTERMSIG(m_status);
        return "killed by signal " + std::to_string(sig) + " (" + strsignal(sig) + ")";
    }
    return "ended";
}

std::vector<std::string> StudentProgram::errorLines() const {
    if (m_tempFolder.empty()) return {};
    FILE* f = std::fopen((m_tempFolder + "/stderr.txt").c_str(), "rb");
    if (!f) return {};
    std::fseek(f, 0, SEEK_END);
    const long size = std::ftell(f);
    const long from = std::max(0L, size - 16384);
    std::fseek(f, from, SEEK_SET);
    std::string text(std::size_t(size - from), '\0');
    text.resize(std::fread(text.data(), 1, text.size(), f));
    std::fclose(f);
    std::vector<std::string> lines = lastLines(text, from > 0);
    return reportLines(lines);
}

std::string StudentProgram::memoryHint() const {
    return memoryHintOf(errorLines(), m_limits.memoryBytes);
}

double StudentProgram::secondsUsed() const {
    return std::chrono::duration<double>(Clock::now() - m_started).count();
}

}  // namespace rasterlab::check
