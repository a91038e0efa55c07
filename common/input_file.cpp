#include "input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "message_text.h"
#include "png_io.h"  // FileError

namespace browser {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void refuse(const fs::path& file, const std::string& reason) {
    throw FileError(printable(file.string()) + ": cannot read: " + reason);
}

// Opens `file` for reading and checks what it is; the descriptor, which the caller closes.
int open_regular(const fs::path& file) {
    const int fd = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) {
        const int error = errno;
        if (error == ENOENT) refuse(file, "no such file");
        if (error == ELOOP) refuse(file, "a loop of symbolic links");
        refuse(file, std::strerror(error));
    }
    struct stat status {};
    const char* wrong = nullptr;
    if (::fstat(fd, &status) != 0) wrong = "it cannot be examined";
    else if (S_ISDIR(status.st_mode)) wrong = "it is a folder";
    else if (S_ISFIFO(status.st_mode)) wrong = "it is a FIFO, not a regular file";
    else if (S_ISCHR(status.st_mode) || S_ISBLK(status.st_mode)) wrong = "it is a device, not a regular file";
    else if (!S_ISREG(status.st_mode)) wrong = "it is not a regular file";
    if (wrong != nullptr) {
        ::close(fd);
        refuse(file, wrong);
    }
    // Reads from now on wait for the data, as reading a regular file does anyway.
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
    return fd;
}

// Appends up to `most` bytes read from `fd` to `text`; how many, 0 at the end.
std::size_t read_some(int fd, const fs::path& file, std::string& text, std::size_t most) {
    char chunk[1 << 16];
    for (;;) {
        const ssize_t got = ::read(fd, chunk, std::min(sizeof chunk, most));
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) refuse(file, std::strerror(errno));
        text.append(chunk, static_cast<std::size_t>(got));
        return static_cast<std::size_t>(got);
    }
}

}  // namespace

std::string read_whole_file(const fs::path& file, std::size_t most_bytes, std::string_view what) {
    const int fd = open_regular(file);
    struct Closer {
        int fd;
        ~Closer() { ::close(fd); }
    } closer{fd};
    const auto too_long = [&] {
        refuse(file,
               "longer than " + std::to_string(most_bytes) + " bytes, the most " + std::string(what) + " may hold");
    };
    struct stat status {};
    if (::fstat(fd, &status) == 0 && status.st_size > static_cast<off_t>(most_bytes)) too_long();
    std::string text;
    // One byte past the limit tells a file that grew while it was read.
    while (read_some(fd, file, text, most_bytes + 1 - text.size()) > 0) {
        if (text.size() > most_bytes) too_long();
    }
    return text;
}

LineReader::LineReader(const fs::path& file, std::size_t longest_line)
    : file_(file), fd_(open_regular(file)), longest_line_(longest_line) {}

LineReader::~LineReader() { ::close(fd_); }

void LineReader::fill() {
    buffer_.erase(0, at_);
    at_ = 0;
    if (read_some(fd_, file_, buffer_, 1 << 16) == 0) ended_ = true;
}

bool LineReader::next(std::string& line) {
    for (;;) {
        const std::size_t end = buffer_.find('\n', at_);
        if (end != std::string::npos) {
            if (end - at_ > longest_line_) break;
            line.assign(buffer_, at_, end - at_);
            at_ = end + 1;
            return true;
        }
        if (buffer_.size() - at_ > longest_line_) break;
        if (ended_) {
            if (at_ == buffer_.size()) return false;
            line.assign(buffer_, at_, std::string::npos);  // a last line with no '\n'
            at_ = buffer_.size();
            return true;
        }
        fill();
    }
    refuse(file_, "a line longer than " + std::to_string(longest_line_) + " bytes");
}

}  // namespace browser
