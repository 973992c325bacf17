// isotrace command-line front end.
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "renderer/core/did_you_mean.h"
#include "renderer/core/input_error.h"
#include "renderer/core/version.h"
#include "renderer/core/printable.h"
#include "tools/cli/commands.h"

namespace {

// "isotrace rendr scene.json" would otherwise be reported as "A subcommand is required".
bool reject_unknown_command(const CLI::App& app, int argc, char** argv) {
    if (argc < 2 || argv[1][0] == '-') return false;
    const std::string word = argv[1];
    std::vector<std::string> names;
    for (const CLI::App* command : app.get_subcommands({})) {
        if (command->check_name(word)) return false;  // its name or an alias
        names.push_back(command->get_name());
    }
    std::string list;
    for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
    const std::string suggestion = isotrace::did_you_mean(word, names);
    std::fprintf(stderr, "isotrace: error: unknown command \"%s\"%s; commands: %s\n", word.c_str(),
                 suggestion.c_str(), list.c_str());
    return true;
}

// Plain "isotrace": what each command does, one line each.
void print_usage(const CLI::App& app) {
    std::printf("%s\n\nusage: isotrace COMMAND [options]   (isotrace COMMAND --help lists its options)\n\ncommands:\n",
                app.get_description().c_str());
    for (const CLI::App* command : app.get_subcommands({})) {
        std::string aliases;
        for (const std::string& alias : command->get_aliases()) aliases += (aliases.empty() ? "" : ", ") + alias;
        std::printf("  %-8s %s%s\n", command->get_name().c_str(), command->get_description().c_str(),
                    aliases.empty() ? "" : (" (alias: " + aliases + ")").c_str());
    }
}

}  // namespace

int main(int argc, char** argv) {
    using namespace isotrace::cli;
    // Past a file-size limit write() then fails with EFBIG and the output code removes its temporary file;
    // SIGXFSZ's default action would kill the process and leave the temporary behind.
    std::signal(SIGXFSZ, SIG_IGN);
    CLI::App app("isotrace - a CPU ray tracer for implicit and procedural surfaces", "isotrace");
    // Set before the sub-commands are added: they copy it.
    app.failure_message([](const CLI::App* failed, const CLI::Error& error) {
        return "isotrace: error: " + CLI::FailureMessage::simple(failed, error);
    });
    app.set_version_flag("--version", std::string("isotrace ") + isotrace::kIsotraceVersion);
    app.require_subcommand(1);
    const CommandRunner render = add_render_command(app);
    const CommandRunner info = add_info_command(app);
    const CommandRunner depth = add_depth_command(app);
    const CommandRunner bench = add_bench_command(app);
    const CommandRunner mesh = add_mesh_command(app);
    const CommandRunner deform = add_deform_command(app);
    const CommandRunner diff = add_diff_command(app);
    if (argc == 1) {
        print_usage(app);
        return kExitOk;
    }
    if (reject_unknown_command(app, argc, argv)) return kExitBadInput;
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
        if (app.got_subcommand("mesh")) return mesh();
        if (app.got_subcommand("deform")) return deform();
        if (app.got_subcommand("diff")) return diff();
        return info();
    } catch (const isotrace::InputError& error) {
        std::fprintf(stderr, "isotrace: error: %s\n", error.what());
        return kExitBadInput;
    } catch (const CLI::ParseError& error) {
        return app.exit(error) == 0 ? kExitOk : kExitBadInput;
    } catch (const std::bad_alloc&) {
        // The memory estimate (--max-memory) should refuse such input first; this is the backstop.
        std::fprintf(stderr, "isotrace: error: out of memory: the scene or options need more memory than is available\n");
        return kExitBadInput;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "isotrace: failure: %s\n", isotrace::printable(error.what()).c_str());
        return kExitFailure;
    }
}
