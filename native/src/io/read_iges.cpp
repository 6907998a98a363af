#include "io/read_iges.h"

#include <fstream>
#include <sstream>

#include "geom/error.h"
#include "io/iges_file.h"
#include "io/iges_reader.h"
#include "io/read_monitor.h"

namespace trimkit::io {

namespace {

// Share of the progress bar the lexical parse takes (it reports no progress itself).
constexpr double kParseShare = 0.1;

}  // namespace

geom::Model read_iges_text(const std::string& text, const std::string& name, const ReadOptions& options) {
    ReadMonitor monitor(name, options);
    monitor.report(0.0);
    const IgesFile file = IgesFile::parse(text, name);
    monitor.check();
    monitor.stage(kParseShare, 1.0);
    IgesReader reader(file, &monitor);
    geom::Model model = reader.read();
    monitor.report(1.0);
    return model;
}

geom::Model read_iges(const std::string& path, const ReadOptions& options) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw geom::ReadError(path, 0, "cannot open file");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) throw geom::ReadError(path, 0, "error while reading the file");
    return read_iges_text(buffer.str(), path, options);
}

}  // namespace trimkit::io
