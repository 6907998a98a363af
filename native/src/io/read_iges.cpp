#include "io/read_iges.h"

#include <fstream>
#include <sstream>

#include "geom/error.h"
#include "io/iges_file.h"
#include "io/iges_reader.h"

namespace trimkit::io {

geom::Model read_iges_text(const std::string& text, const std::string& name) {
    const IgesFile file = IgesFile::parse(text, name);
    IgesReader reader(file);
    return reader.read();
}

geom::Model read_iges(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw geom::ReadError(path, 0, "cannot open file");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) throw geom::ReadError(path, 0, "error while reading the file");
    return read_iges_text(buffer.str(), path);
}

}  // namespace trimkit::io
