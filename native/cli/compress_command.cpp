// trimkit compress MODEL -o OUT.tkz [--tolerance T]: each face's surface refitted
// from its boundary edges with G1 to its neighbours ([Muraki], fit::compress_model);
// faces within the tolerance keep only their rule. Prints a line per face and the
// sizes: the source file, the same .tkz with every surface kept, and the .tkz.
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "arguments.h"
#include "commands.h"
#include "fit/compress_model.h"
#include "io/read_model.h"
#include "io/tkz_format.h"

namespace trimkit::cli {
namespace {

const char* const kCompressUsage = "trimkit compress MODEL -o OUT.tkz [--tolerance T]";

std::string face_line(int f, const fit::FaceCompression& c) {
    char buf[512];
    if (c.compressed)
        std::snprintf(buf, sizeof buf,
                      "face %d: compressed (%s, degree %dx%d, %dx%d points, %d G1 edges, G1 max %.3g deg) avg %.3g "
                      "max %.3g ratio %.4f%% edges max %.3g, back %.3g, tolerance %.3g\n",
                      f, c.rule.method == fit::FitMethod::kCoons ? "coons" : "boundary fit", c.rule.degree_u,
                      c.rule.degree_v, c.rule.count_u, c.rule.count_v, c.g1_edges, c.g1_angle,
                      c.error.surface_avg, c.error.max(), 100 * c.error.ratio(), c.error.edge_max, c.reverse_max,
                      c.tolerance);
    else
        std::snprintf(buf, sizeof buf, "face %d: kept (%s)\n", f, c.reason.c_str());
    return buf;
}

}  // namespace

int run_compress(const std::vector<std::string>& argv) {
    const Arguments args(argv, {}, {"--output", "--tolerance"});
    args.expect_positionals(1, kCompressUsage);
    if (!args.has("--output")) throw UsageError(std::string("missing -o OUT.tkz; usage: ") + kCompressUsage);
    fit::CompressOptions options;
    options.tolerance = args.number("--tolerance", 0.0);
    if (args.has("--tolerance") && !(options.tolerance > 0))
        throw UsageError("option --tolerance = " + args.value("--tolerance", "") + "; expected a length > 0");
    const std::string& path = args.positionals()[0];
    const geom::Model model = io::read_model(path);
    std::vector<fit::FaceCompression> report;
    const fit::CompressedModel compressed = fit::compress_model(model, options, &report);
    int count = 0;
    double worst = 0;
    for (std::size_t f = 0; f < report.size(); ++f) {
        std::cout << face_line(static_cast<int>(f), report[f]);
        if (report[f].compressed) ++count, worst = std::max(worst, report[f].error.max());
    }
    const std::string bytes = io::tkz_bytes(compressed);
    fit::CompressedModel all_kept{model, std::vector<std::optional<fit::FitRule>>(model.faces.size())};
    const std::size_t kept_bytes = io::tkz_bytes(all_kept).size();
    const auto source_bytes = std::filesystem::file_size(path);
    io::write_tkz(compressed, args.value("--output", ""));
    std::printf("faces: %d of %zu compressed, max error %.4g\n", count, report.size(), worst);
    std::printf("bytes: source %ju, tkz with every surface kept %zu, tkz %zu\n", static_cast<std::uintmax_t>(source_bytes),
                kept_bytes, bytes.size());
    std::printf("size ratio: %.4f of the source (%.1f%% smaller), %.4f of the kept-surface tkz (%.1f%% smaller)\n",
                double(bytes.size()) / source_bytes, 100.0 * (1 - double(bytes.size()) / source_bytes),
                double(bytes.size()) / kept_bytes, 100.0 * (1 - double(bytes.size()) / kept_bytes));
    return 0;
}

}  // namespace trimkit::cli
