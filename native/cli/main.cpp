// `trimkit`: the command-line program. Dispatches to one subcommand and turns
// exceptions into one stderr line "trimkit: FILE:LINE: what is wrong" with exit
// status 2 for bad input or usage and 1 for internal failures.
#include <exception>
#include <functional>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "arguments.h"
#include "commands.h"
#include "geom/error.h"
#include "io/read_options.h"

namespace {

const char* const kUsage =
    "usage: trimkit COMMAND [ARGS]\n"
    "commands:\n"
    "  info MODEL [--json] [--read-timeout S] [--step-reader occt|own|auto]\n"
    "                         summary of an IGES, STEP or .brep model: units, faces, surfaces, loops, edges\n"
    "  mesh MODEL -o OUT --tolerance T [--relative] [--angle DEG] [--mode guaranteed|approximate]\n"
    "       [--trim-method bezier3d|yang|param] [--threads N] [--face-timeout S] [--read-timeout S]\n"
    "       [--step-reader occt|own|auto]\n"
    "       [--json] [--strict]\n"
    "                         tessellate to .obj .ply .stl .glb within T (model units);\n"
    "                         --strict: exit 3 if a face failed its check or the reader left one out\n"
    "                         (one stderr line each);\n"
    "                         --face-timeout: seconds per face (default 30, 0 = none), a slower face fails;\n"
    "                         --read-timeout: seconds for reading MODEL (default 120, 0 = none), exit 2;\n"
    "                         --step-reader: STEP read by Open CASCADE (default), by trimkit's own reader\n"
    "                         (parts and assemblies of the kinds it translates; others refused) or by its\n"
    "                         own with OCCT for what it refuses (auto)\n"
    "  check MODEL MESH [--json] [--samples N] [--threads N] [--read-timeout S]\n"
    "                         two-sided deviation of MESH from MODEL's faces, area ratio, open edges\n"
    "  check MODEL_A MODEL_B  two-sided surface deviation per face between two models (.igs .stp .brep .tkz)\n"
    "  compress MODEL -o OUT.tkz [--tolerance T]\n"
    "                         refit each face from its boundary edges with G1 (Muraki); faces within T\n"
    "                         (default 1% of each face's box) keep only the rule\n"
    "  extend IN.tkz -o MODEL.igs\n"
    "                         rebuild the compressed faces and write IGES (B-rep where the model has it)\n"
    "  tbp mesh|intersect|trim|inside|from-mesh ...\n"
    "                         TBP solids (.tbp): mesh at a level/lod, intersect, trim, point-in-solid, PN triangles\n";

int fail(int status, const std::string& message) {
    std::cerr << "trimkit: " << message << "\n";
    return status;
}

}  // namespace

int main(int argc, char** argv) {
    using Command = std::function<int(const std::vector<std::string>&)>;
    const std::map<std::string, Command> commands = {
        {"info", trimkit::cli::run_info},
        {"mesh", trimkit::cli::run_mesh},
        {"check", trimkit::cli::run_check},
        {"tbp", trimkit::cli::run_tbp},
        {"compress", trimkit::cli::run_compress},
        {"extend", trimkit::cli::run_extend},
    };
    if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
        std::cout << kUsage;
        return argc < 2 ? 2 : 0;
    }
    const auto command = commands.find(argv[1]);
    if (command == commands.end()) {
        std::cerr << kUsage;
        return fail(2, std::string("unknown command '") + argv[1] + "'");
    }
    try {
        return command->second(std::vector<std::string>(argv + 2, argv + argc));
    } catch (const trimkit::cli::UsageError& e) {
        return fail(2, e.what());
    } catch (const trimkit::io::ReadStopped& e) {
        // "FILE: reading stopped after N s (--read-timeout)": the option that sets the limit.
        std::string what = e.what();
        const std::string library = "(read timeout)";
        const size_t at = what.rfind(library);
        if (at != std::string::npos) what.replace(at, library.size(), "(--read-timeout)");
        return fail(2, what);
    } catch (const trimkit::geom::ReadError& e) {
        return fail(2, e.what());
    } catch (const trimkit::geom::InvalidInput& e) {
        return fail(2, e.what());
    } catch (const std::bad_alloc&) {
        return fail(1, "out of memory");
    } catch (const std::exception& e) {
        return fail(1, std::string("internal error: ") + e.what());
    }
}
