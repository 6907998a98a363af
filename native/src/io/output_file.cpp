#include "io/output_file.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include <unistd.h>

namespace trimkit::io {
namespace {

std::string reason() { return errno != 0 ? std::strerror(errno) : "unknown error"; }

// A name beside `path` that no other writer of this process or another uses.
std::string temporary_name(const std::string& path) {
    static std::atomic<unsigned long> counter{0};
    return path + ".partial-" + std::to_string(getpid()) + "-" + std::to_string(counter++);
}

bool special_file(const std::string& path) {
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    return !ec && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status);
}

}  // namespace

OutputFile::OutputFile(const std::string& path)
    : path_(path), temporary_(special_file(path) ? path : temporary_name(path)) {
    errno = 0;
    out_.open(temporary_, std::ios::binary | std::ios::trunc);
    if (!out_.is_open()) throw std::runtime_error(path_ + ": cannot open for writing (" + reason() + ")");
}

OutputFile::~OutputFile() {
    if (committed_ || temporary_ == path_) return;
    out_.close();
    std::remove(temporary_.c_str());
}

void OutputFile::commit() {
    errno = 0;
    out_.flush();
    const bool written = out_.good();
    out_.close();
    if (!written || out_.fail()) throw std::runtime_error(path_ + ": write failed (" + reason() + ")");
    if (temporary_ != path_) {
        std::error_code ec;
        std::filesystem::rename(temporary_, path_, ec);
        if (ec) throw std::runtime_error(path_ + ": write failed (renaming " + temporary_ + ": " + ec.message() + ")");
    }
    committed_ = true;
}

}  // namespace trimkit::io
