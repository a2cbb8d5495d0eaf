// Spilling (rtig --spill-dir, --disk-budget; docs/robustness.md): a client that stops reading, a federate
// paused in a debugger above all, holds nobody back. What the gateway writes for it beyond its budget goes
// to a file of its own, read back in order as the client takes what is in memory, while its publishers and
// every other client go on at full speed. The files have no name (O_TMPFILE, else unlinked at once), so
// nothing is left behind however the gateway ends; what was read back is given back to the disk as it goes
// (hole punching), and all of it when the file is drained. The files share one disk budget: a spill that
// would go beyond it, a full disk or a directory that refuses throws SpillError, and the gateway drops that
// one connection saying so.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

namespace hlacore {

class SpillError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The disk budget every spill file shares, and where they are made.
struct SpillBudget {
    std::string directory;    // "": $TMPDIR, else /tmp
    std::uint64_t limit = 0;  // bytes on disk at most; 0: no spilling
    std::uint64_t used = 0;
    bool on() const { return limit > 0; }
};

// Bytes on disk for one connection: a FIFO (its stream's backlog: append, read), or frames read back in any
// order (the messages time management parks: append, read_at, release). Emptied, and all its disk given
// back, once every byte written was read back or released.
class SpillFile {
public:
    explicit SpillFile(SpillBudget& budget);  // SpillError when no file can be made
    ~SpillFile();
    SpillFile(const SpillFile&) = delete;
    SpillFile& operator=(const SpillFile&) = delete;

    // Returns where `bytes` start, for read_at (SpillError: budget spent, disk full, I/O error).
    std::uint64_t append(std::string_view bytes);
    // As a FIFO: appends up to `max` of the oldest bytes to `out` and returns how many (SpillError on an I/O
    // error); what was read goes back to the disk.
    std::size_t read(std::string& out, std::size_t max);
    std::uint64_t size() const { return written_ - released_; }  // bytes not read back or released yet
    // By place: appends the `size` bytes written at `at` to `out`; release() gives them up once read.
    void read_at(std::uint64_t at, std::size_t size, std::string& out);
    void release(std::uint64_t size);
    const std::string& directory() const { return directory_; }
    static std::string directory_for(const SpillBudget& budget);  // budget.directory, else $TMPDIR or /tmp

private:
    void give_back(std::uint64_t upto);  // frees the disk under [punched_, upto)
    SpillBudget& budget_;
    std::string directory_;
    int fd_ = -1;
    std::uint64_t written_ = 0;   // file offsets: the end,
    std::uint64_t front_ = 0;     // as a FIFO, what was read back,
    std::uint64_t punched_ = 0;   // and what was given back to the disk;
    std::uint64_t released_ = 0;  // bytes read back or released
};

}  // namespace hlacore
