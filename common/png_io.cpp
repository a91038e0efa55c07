#include "png_io.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <system_error>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

#include <stb_image.h>
#include <stb_image_write.h>

#include "interruption.h"
#include "message_text.h"

namespace browser {

namespace fs = std::filesystem;

namespace {

// Every PNG file starts with these 8 bytes.
constexpr std::array<unsigned char, 8> kPngSignature{0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};

[[noreturn]] void fail(const char* doing, const fs::path& path, const std::string& reason) {
    throw FileError(std::string(doing) + " " + printable(path.string()) + ": " + reason);
}

// The folder a file goes into: "." for a bare file name.
fs::path folder_of(const fs::path& path) { return path.has_parent_path() ? path.parent_path() : fs::path("."); }

// stb_image_write hands the encoded bytes over in pieces; we collect them in memory so
// that file errors are ours to report.
void append_bytes(void* context, void* data, int size) {
    auto& bytes = *static_cast<std::vector<unsigned char>*>(context);
    const auto* first = static_cast<const unsigned char*>(data);
    bytes.insert(bytes.end(), first, first + size);
}

}  // namespace

void write_png(const fs::path& path, const Image& image) {
    constexpr const char* kDoing = "cannot write PNG";
    if (image.width <= 0 || image.height <= 0) fail(kDoing, path, "the picture is empty");

    std::error_code error;
    const fs::path folder = folder_of(path);
    if (!fs::is_directory(folder, error)) {
        const bool exists = fs::exists(folder, error);
        fail(kDoing, path, (exists ? "not a folder: " : "folder does not exist: ") + folder.string());
    }

    std::vector<unsigned char> bytes;
    if (!stbi_write_png_to_func(append_bytes, &bytes, image.width, image.height, 4, image.rgba.data(),
                                image.width * 4)) {
        fail(kDoing, path, "the PNG encoder failed");
    }

    // Written beside the final name and renamed into place: a rename within one folder
    // replaces the old file at once, so nobody ever reads half a picture. The partial
    // file's name is this process's own and is made new (O_EXCL, O_NOFOLLOW): a file or a
    // link already there under that name is never written through. An interruption
    // removes it (interruption.h).
    fs::path temporary = path;
    temporary += ".partial" + process_suffix();
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd < 0) fail(kDoing, path, std::strerror(errno));
    const Leftover leftover(temporary);
    std::FILE* file = ::fdopen(fd, "wb");
    if (!file) {
        const int reason = errno;
        ::close(fd);
        fs::remove(temporary, error);
        fail(kDoing, path, std::strerror(reason));
    }
    const bool written = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
    const int write_errno = errno;
    const bool closed = std::fclose(file) == 0;
    if (!written || !closed) {
        const int reason = written ? errno : write_errno;
        fs::remove(temporary, error);
        fail(kDoing, path, std::strerror(reason));
    }
    fs::rename(temporary, path, error);
    if (error) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        fail(kDoing, path, error.message());
    }
}

Image decode_png(std::span<const unsigned char> bytes) {
    if (bytes.size() < kPngSignature.size() || !std::equal(kPngSignature.begin(), kPngSignature.end(), bytes.begin())) {
        throw FileError("not a PNG file");
    }
    if (bytes.size() > kLargestPngFile) throw FileError("it is larger than a picture of a run can be");
    // stb_image grows its buffer for the picture's data by what each chunk's length says
    // before it reads the chunk: a 93-byte file claiming a 2 GB chunk made it ask for 2 GB
    // (found by fuzz/png_reader). Each image-data chunk must fit the file.
    for (std::size_t at = kPngSignature.size(); at + 8 <= bytes.size();) {
        const std::uint64_t length = (std::uint64_t{bytes[at]} << 24) | (std::uint64_t{bytes[at + 1]} << 16) |
                                     (std::uint64_t{bytes[at + 2]} << 8) | std::uint64_t{bytes[at + 3]};
        const auto type = bytes.begin() + static_cast<std::ptrdiff_t>(at + 4);
        if (at + 12 + length > bytes.size() && std::equal(type, type + 4, "IDAT")) {
            throw FileError("damaged PNG file (a chunk runs past the end of the file)");
        }
        if (at + 12 + length > bytes.size()) break;  // stb names what else is wrong
        if (std::equal(bytes.begin() + static_cast<std::ptrdiff_t>(at + 4),
                       bytes.begin() + static_cast<std::ptrdiff_t>(at + 8), "IEND"))
            break;
        at += 12 + static_cast<std::size_t>(length);
    }
    const int size = static_cast<int>(bytes.size());
    int width = 0, height = 0, channels_in_file = 0;
    // The header says how large the picture is; a small file can unpack to gigabytes.
    if (stbi_info_from_memory(bytes.data(), size, &width, &height, &channels_in_file) &&
        static_cast<double>(width) * height > kMostPngPixels) {
        throw FileError("it is " + std::to_string(width) + " x " + std::to_string(height) + " pixels, more than the " +
                        std::to_string(static_cast<long>(kMostPngPixels)) + " a picture may have");
    }
    unsigned char* pixels = stbi_load_from_memory(bytes.data(), size, &width, &height, &channels_in_file, 4);
    // stb names an unknown chunk by its four bytes, whatever they are (found by fuzz/png_reader).
    if (!pixels) throw FileError("damaged PNG file (" + printable(stbi_failure_reason()) + ")");
    Image image;
    image.width = width;
    image.height = height;
    image.rgba.assign(pixels, pixels + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    stbi_image_free(pixels);
    return image;
}

Image read_png(const fs::path& path) {
    constexpr const char* kDoing = "cannot read PNG";
    std::error_code error;
    const fs::file_status status = fs::status(path, error);  // through links: a link to a picture is read
    if (!fs::exists(status)) fail(kDoing, path, "no such file");
    if (fs::is_directory(status)) fail(kDoing, path, "it is a folder");
    // A FIFO would wait for a writer for ever, a device such as /dev/zero never ends.
    if (fs::is_fifo(status)) fail(kDoing, path, "it is a FIFO, not a regular file");
    if (fs::is_character_file(status) || fs::is_block_file(status))
        fail(kDoing, path, "it is a device, not a regular file");
    if (!fs::is_regular_file(status)) fail(kDoing, path, "it is not a regular file");
    if (fs::file_size(path, error) > kLargestPngFile) fail(kDoing, path, "it is larger than a picture of a run can be");

    std::ifstream in(path, std::ios::binary);
    if (!in) fail(kDoing, path, std::strerror(errno));
    const std::vector<unsigned char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    try {
        return decode_png(bytes);
    } catch (const FileError& error) {
        fail(kDoing, path, error.what());
    }
}

}  // namespace browser
