// A student's program, run as untrusted code: started from a command line in its own folder,
// in a process group of its own, with limits on wall-clock time (per request and in all), CPU
// time, memory, file size, processes and the bytes it may answer with; inside bubblewrap
// (bwrap) where it is installed and works, with no network and the file system read-only but
// for a temporary folder. Its standard output is read line by line with a deadline: it never
// blocks RasterLab longer than the limits, and whatever it does (hang, flood, write binary,
// never end a line, exit, crash) becomes a message that says what was read last.
#pragma once

#include <atomic>
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rasterlab::check {

class PidsCgroup;

inline constexpr int kErrorLines = 12;
inline constexpr int kErrorLineBytes = 200;

struct Limits {
    double requestSeconds = 20.0;  // wall clock, for one request's answer
    double totalSeconds = 120.0;   // wall clock, for the whole run
    int cpuSeconds = 100;
    // Memory it may use (its data: heap and private writable mappings, RLIMIT_DATA), not its
    // address space, which a runtime (a JVM, .NET, node) reserves far beyond what it uses;
    // 0: not limited.
    long long memoryBytes = 2LL << 30;
    long long fileBytes = 64LL << 20;    // any file it writes, its standard error included
    long long answerBytes = 64LL << 20;  // the bytes of one answer
    long long answerLines = 4LL << 20;   // its lines
    int lineBytes = 1 << 20;             // the longest line of an answer
    int processes = 64;
    bool sandbox = true;  // bubblewrap, where installed
    // Set from another thread (the window's Cancel): the program is stopped within a tenth of
    // a second, and the read or write that waited says "cancelled".
    const std::atomic<bool>* cancel = nullptr;
};

class StudentProgram {
public:
    // Starts `command` with /bin/sh in `folder`. Nothing is thrown: a program that cannot be
    // started gives a process that has ended, whose reads say why. With inTemporaryFolder the
    // folder is first copied into the temporary folder and the program runs in the copy, where
    // it may write (an HW2 renderer writes its PNG images beside itself).
    StudentProgram(const std::string& command, const std::string& folder, const Limits& limits,
                   bool inTemporaryFolder = false);
    ~StudentProgram();  // kills the program's whole process group
    StudentProgram(const StudentProgram&) = delete;
    StudentProgram& operator=(const StudentProgram&) = delete;

    // The protections that applied, and those that did not, each in a few words.
    const std::vector<std::string>& protections() const { return m_protections; }
    const std::vector<std::string>& missingProtections() const { return m_missing; }

    // Writes to the program's standard input; false (and error() says why) when it is gone.
    bool send(const std::string& text);
    // Starts the clock of one request.
    void beginRequest();
    // The next line of its standard output, without the line end; nullopt on a failure:
    // error() then says what happened and what was read last.
    std::optional<std::string> readLine();
    const std::string& error() const { return m_error; }
    // The last lines of its standard error (at most kErrorLines lines of kErrorLineBytes),
    // with the line that opens an exception's report where the last lines would cut it off.
    std::vector<std::string> errorLines() const;
    // When those lines are a runtime's out-of-memory message: a hint that names the limit.
    std::string memoryHint() const;
    // Ends the program: closes its input, waits a moment, then kills its group.
    void stop();
    // A program that is not asked over the protocol (an HW2 renderer run on a command file):
    // its input closed, its output read and dropped, until it ends or the whole run's time is
    // up (then it is killed). False, and error() says why, unless it ended with status 0.
    bool waitForExit();
    // The temporary folder (TMPDIR and HOME, writable inside the sandbox); removed with the
    // program.
    const std::string& temporaryFolder() const { return m_tempFolder; }
    // How the program ended, as words: "exit status 1", "killed by signal 11 (segmentation
    // fault)"; empty while it runs.
    std::string ending();
    double secondsUsed() const;

private:
    bool fail(const std::string& message);
    bool fillBuffer(std::chrono::steady_clock::time_point deadline);
    // Milliseconds to wait in one poll: until the deadline, at most a tenth of a second.
    int pollMilliseconds(std::chrono::steady_clock::time_point deadline) const;
    bool cancelled() const { return m_limits.cancel && m_limits.cancel->load(); }
    void startProcess(const std::string& command, const std::string& folder,
                      bool inTemporaryFolder);
    std::vector<std::string> arguments(const std::string& command, const std::string& folder);
    void reap(bool wait);

    Limits m_limits;
    std::unique_ptr<PidsCgroup> m_cgroup;  // bounds the processes where RLIMIT_NPROC does not
    std::vector<std::string> m_protections, m_missing;
    std::string m_error;
    std::string m_tempFolder;
    int m_pid = -1;
    int m_stdin = -1, m_stdout = -1;
    int m_status = -1;  // waitpid's, once reaped
    bool m_reaped = false;
    bool m_talked = false;  // asked over the protocol (send was called)
    std::string m_buffer;   // read; lines from m_bufferStart on not yet returned
    std::size_t m_bufferStart = 0;
    std::string m_lastLine;
    long long m_answerBytes = 0, m_answerLines = 0;
    std::chrono::steady_clock::time_point m_started, m_requestDeadline, m_totalDeadline;
};

// When these lines (of a program's standard error or output) are a runtime's out-of-memory
// message: a hint that names the limit (`memoryBytes`, 0 for none), else empty.
std::string memoryHintOf(const std::vector<std::string>& lines, long long memoryBytes);

// Whether bubblewrap is installed and can make a sandbox here (a user namespace may be
// refused, inside a container); the reason when not.
bool sandboxUsable(std::string* reason);

}  // namespace rasterlab::check
