// isotrace command-line front end.
#include <cstdio>
#include <exception>

#include "renderer/core/input_error.h"
#include "renderer/core/version.h"
#include "tools/cli/commands.h"

int main(int argc, char** argv) {
    using namespace isotrace::cli;
    CLI::App app("isotrace - a CPU ray tracer for implicit and procedural surfaces", "isotrace");
    app.set_version_flag("--version", std::string("isotrace ") + isotrace::kIsotraceVersion);
    app.require_subcommand(1);
    const CommandRunner render = add_render_command(app);
    const CommandRunner info = add_info_command(app);
    const CommandRunner depth = add_depth_command(app);
    const CommandRunner bench = add_bench_command(app);
    const CommandRunner polygonize = add_polygonize_command(app);
    const CommandRunner deform = add_deform_command(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        const int code = app.exit(error);
        return code == 0 ? kExitOk : kExitBadInput;
    }
    try {
        if (app.got_subcommand("render")) return render();
        if (app.got_subcommand("depth")) return depth();
        if (app.got_subcommand("bench")) return bench();
        if (app.got_subcommand("polygonize")) return polygonize();
        if (app.got_subcommand("deform")) return deform();
        return info();
    } catch (const isotrace::InputError& error) {
        std::fprintf(stderr, "isotrace: error: %s\n", error.what());
        return kExitBadInput;
    } catch (const CLI::ParseError& error) {
        return app.exit(error) == 0 ? kExitOk : kExitBadInput;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "isotrace: failure: %s\n", error.what());
        return kExitFailure;
    }
}
