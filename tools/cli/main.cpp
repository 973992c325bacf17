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

using namespace isotrace::cli;

// Every command, in the order plain "isotrace" lists them: the sub-commands, that listing and the unknown-command
// message all come from this table.
struct Command {
    const char* name;
    const char* summary;
    const char* alias;  // another name the command answers to, or nullptr
    CommandRunner (*add_options)(CLI::App* command);
};

constexpr Command kCommands[] = {
    {"render", "Render a scene to image files", nullptr, add_render_options},
    {"info", "Validate a scene and print a summary, or list the plugins or the OCIO views", nullptr,
     add_info_options},
    {"depth", "Write a range image: view depth as 256 grey levels, near white, far black", nullptr,
     add_depth_options},
    {"bench", "Time fixed workloads (rays, path tracing, polygonising), for developers", nullptr, add_bench_options},
    {"benchmark", "Run the frozen benchmark suite: validated outputs, one score to quote", nullptr,
     add_benchmark_options},
    // "polygonize": the blob-only tessellator this command replaced.
    {"mesh", "Polygonise an implicit object, or write a traced one's triangles", "polygonize", add_mesh_options},
    {"deform", "Apply mesh deformers (sweep-based free-form deformation) to a mesh file", nullptr,
     add_deform_options},
    {"diff", "Compare an image with a reference, or z-test a render", nullptr, add_diff_options},
};

// "isotrace rendr scene.json" would otherwise be reported as "A subcommand is required".
bool reject_unknown_command(int argc, char** argv) {
    if (argc < 2 || argv[1][0] == '-') return false;
    const std::string word = argv[1];
    std::vector<std::string> names;
    std::string list;
    for (const Command& command : kCommands) {
        if (word == command.name || (command.alias != nullptr && word == command.alias)) return false;
        names.push_back(command.name);
        list += (list.empty() ? "" : ", ") + names.back();
    }
    const std::string suggestion = isotrace::did_you_mean(word, names);
    std::fprintf(stderr, "isotrace: error: unknown command \"%s\"%s; commands: %s\n", word.c_str(),
                 suggestion.c_str(), list.c_str());
    return true;
}

// Plain "isotrace": what each command does, one line each.
void print_usage(const CLI::App& app) {
    std::printf("%s\n\nusage: isotrace COMMAND [options]   (isotrace COMMAND --help lists its options)\n\ncommands:\n",
                app.get_description().c_str());
    for (const Command& command : kCommands) {
        const std::string alias = command.alias == nullptr ? "" : std::string(" (alias: ") + command.alias + ")";
        std::printf("  %-9s %s%s\n", command.name, command.summary, alias.c_str());
    }
}

}  // namespace

int main(int argc, char** argv) {
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
    std::vector<std::pair<const CLI::App*, CommandRunner>> runners;
    for (const Command& command : kCommands) {
        CLI::App* subcommand = app.add_subcommand(command.name, command.summary);
        if (command.alias != nullptr) subcommand->alias(command.alias);
        runners.emplace_back(subcommand, command.add_options(subcommand));
    }
    if (argc == 1) {
        print_usage(app);
        return kExitOk;
    }
    if (reject_unknown_command(argc, argv)) return kExitBadInput;
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        const int code = app.exit(error);
        return code == 0 ? kExitOk : kExitBadInput;
    }
    try {
        for (const auto& [subcommand, run] : runners) {
            if (subcommand->parsed()) return run();
        }
        return kExitFailure;  // unreachable: require_subcommand(1) made CLI11 reject a line without one
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
