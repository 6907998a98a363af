// An output file that appears whole or not at all: bytes go to a temporary file
// beside the target ("PATH.partial-PID-N", same directory, so the rename stays on
// one file system), and commit() renames it onto PATH. An interrupted or failed
// write (an exception, a full disk, the process killed) leaves the old PATH as it
// was; the destructor removes the temporary file unless commit() succeeded.
// Targets that exist and are not regular files (/dev/null, a pipe) are written
// in place: there is nothing to protect and a rename would replace the device.
#pragma once

#include <fstream>
#include <string>

namespace trimkit::io {

class OutputFile {
public:
    // Opens the temporary file for binary writing; throws std::runtime_error
    // "PATH: cannot open for writing (REASON)" when it cannot be created.
    explicit OutputFile(const std::string& path);
    ~OutputFile();
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    std::ofstream& stream() { return out_; }
    void write(const std::string& bytes) { out_.write(bytes.data(), static_cast<std::streamsize>(bytes.size())); }

    // Flushes, closes and renames onto the target; throws std::runtime_error
    // "PATH: write failed (REASON)" if a write, the close or the rename failed
    // (the temporary file is then removed and PATH left untouched).
    void commit();

    const std::string& path() const { return path_; }
    const std::string& temporary_path() const { return temporary_; }  // == path() when written in place

private:
    std::string path_, temporary_;
    std::ofstream out_;
    bool committed_ = false;
};

}  // namespace trimkit::io
