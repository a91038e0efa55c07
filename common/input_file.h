#pragma once
// Files a tool reads (compare_runs' scene, first_divergence's dumps): only regular
// files, opened without blocking and checked once open, so that a FIFO with no writer
// is refused rather than waited on for ever, a device such as /dev/zero rather than
// read without end, and a folder with one line rather than an abort. What is read is
// bounded: a whole file by its size, a file read line by line by the length of a line.
// Every refusal is a FileError (png_io.h) of one line, "<file>: cannot read: <reason>".

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace browser {

// The whole of `file`, when it is a regular file of at most `most_bytes`. A longer one
// is refused as "longer than N bytes, the most <what> may hold".
std::string read_whole_file(const std::filesystem::path& file, std::size_t most_bytes, std::string_view what = "it");

// A regular file read one line at a time, a buffer's worth of it in memory at once.
class LineReader {
public:
    // Opens `file` (checked as above); `longest_line` bounds a line, in bytes.
    LineReader(const std::filesystem::path& file, std::size_t longest_line);
    ~LineReader();
    LineReader(const LineReader&) = delete;
    LineReader& operator=(const LineReader&) = delete;

    // The next line, without its '\n', into `line`; false at the end of the file.
    // Throws FileError for a line longer than the bound, or a failed read.
    bool next(std::string& line);

private:
    void fill();

    std::filesystem::path file_;
    int fd_ = -1;
    std::size_t longest_line_;
    std::string buffer_;
    std::size_t at_ = 0;  // the next unread byte of buffer_
    bool ended_ = false;
};

}  // namespace browser
