// A spill file (spill.hpp): unnamed, written at its end, read from its start, given back as it is read.
#include "rti/server/spill.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>

#include <fcntl.h>
#include <unistd.h>

namespace hlacore {
namespace {

constexpr std::uint64_t kPunchBytes = 1u << 20;  // given back to the disk in steps of at least this much

[[noreturn]] void fail(const std::string& what, const std::string& directory) {
    throw SpillError(what + " in " + directory + ": " + std::strerror(errno));
}

}  // namespace

std::string SpillFile::directory_for(const SpillBudget& budget) {
    if (!budget.directory.empty()) return budget.directory;
    const char* tmp = std::getenv("TMPDIR");
    return tmp && *tmp ? tmp : "/tmp";
}

SpillFile::SpillFile(SpillBudget& budget) : budget_(budget), directory_(directory_for(budget)) {
    fd_ = ::open(directory_.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
    if (fd_ < 0 && (errno == EOPNOTSUPP || errno == EISDIR || errno == EINVAL)) {  // no O_TMPFILE there
        std::string path = directory_ + "/hlacore-spill-XXXXXX";
        fd_ = ::mkostemp(path.data(), O_CLOEXEC);
        if (fd_ >= 0) ::unlink(path.c_str());
    }
    if (fd_ < 0) fail("cannot make a spill file", directory_);
}

SpillFile::~SpillFile() {
    budget_.used -= written_ - punched_;
    ::close(fd_);
}

std::uint64_t SpillFile::append(std::string_view bytes) {
    if (budget_.used + bytes.size() > budget_.limit)
        throw SpillError("the disk budget of the spill files (" + std::to_string(budget_.limit) + " bytes in " +
                         directory_ + ") is spent");
    for (std::size_t done = 0; done < bytes.size();) {
        const ssize_t n = ::pwrite(fd_, bytes.data() + done, bytes.size() - done, static_cast<off_t>(written_ + done));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            if (n == 0) errno = ENOSPC;
            [[maybe_unused]] const int kept = ::ftruncate(fd_, static_cast<off_t>(written_));  // not the part written
            fail("cannot spill", directory_);
        }
        done += static_cast<std::size_t>(n);
    }
    const std::uint64_t at = written_;
    written_ += bytes.size();
    budget_.used += bytes.size();
    return at;
}

void SpillFile::read_at(std::uint64_t at, std::size_t size, std::string& out) {
    const std::size_t start = out.size();
    out.resize(start + size);
    for (std::size_t got = 0; got < size;) {
        const ssize_t n = ::pread(fd_, out.data() + start + got, size - got, static_cast<off_t>(at + got));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            out.resize(start);
            if (n == 0) errno = EIO;
            fail("cannot read a spill file back", directory_);
        }
        got += static_cast<std::size_t>(n);
    }
}

void SpillFile::release(std::uint64_t size) {
    released_ += size;
    if (released_ < written_) return;
    [[maybe_unused]] const int emptied = ::ftruncate(fd_, 0);  // all read back: the file starts again
    budget_.used -= written_ - punched_;
    written_ = front_ = punched_ = released_ = 0;
}

std::size_t SpillFile::read(std::string& out, std::size_t max) {
    const std::size_t want = static_cast<std::size_t>(std::min<std::uint64_t>(max, written_ - front_));
    read_at(front_, want, out);
    front_ += want;
    const std::uint64_t front = front_;
    release(want);
    if (front_ != 0 && front - punched_ >= kPunchBytes) give_back(front & ~std::uint64_t{4095});
    return want;
}

void SpillFile::give_back(std::uint64_t upto) {
    // Where the file system cannot punch holes, the space comes back when the file is drained.
    if (upto <= punched_ ||
        ::fallocate(fd_, FALLOC_FL_PUNCH_HOLE | FALLOC_FL_KEEP_SIZE, static_cast<off_t>(punched_),
                    static_cast<off_t>(upto - punched_)) != 0)
        return;
    budget_.used -= upto - punched_;
    punched_ = upto;
}

}  // namespace hlacore
