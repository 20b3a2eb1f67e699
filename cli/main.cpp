// facetlight: the command-line face of the photon-mapping core.
#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "commands.h"
#include "process_communicator.h"
#include "util/closest_name.h"
#include "util/error.h"
#include "util/simd_target.h"

namespace {

// "; did you mean '--photons'?" for the first word of the command line that is neither an option of the
// subcommand given nor a subcommand, when one is close to it.
std::string suggestion(CLI::App& app, int argc, char** argv) {
    const std::vector<CLI::App*> given = app.get_subcommands();
    std::vector<std::string> names;
    if (given.empty()) {
        for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
            names.push_back(sub->get_name());
        return argc > 1 ? facetlight::didYouMean(argv[1], names) : "";
    }
    for (const CLI::Option* option : given.front()->get_options())
        for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    for (int i = 2; i < argc; ++i) {
        std::string word = argv[i];
        if (!word.starts_with("--")) continue;
        word = word.substr(0, word.find('='));
        if (std::find(names.begin(), names.end(), word) != names.end()) continue;
        const std::string hint = facetlight::didYouMean(word, names);
        if (!hint.empty()) return hint;
    }
    return "";
}

}  // namespace

int main(int argc, char** argv) {
    facetlight::cli::processCommunicator();  // under mpirun, every rank starts MPI before anything else
    CLI::App app{"facetlight: how light moves through cut gemstones"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "facetlight 0.1.0 (SIMD: " + facetlight::simdTarget() + ")");
    facetlight::cli::addInfoCommand(app);
    facetlight::cli::addCutCommand(app);
    facetlight::cli::addTraceCommand(app);
    facetlight::cli::addStudyCommand(app);
    facetlight::cli::addRenderCommand(app);
    facetlight::cli::addSweepCommand(app);
    facetlight::cli::addPolariscopeCommand(app);
    facetlight::cli::addDoublingCommand(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
        std::cerr << "facetlight: " << e.what() << suggestion(app, argc, argv)
                  << "\nRun with --help for more information.\n";
        return e.get_exit_code();
    } catch (const facetlight::Error& e) {
        std::cerr << "facetlight: " << e.what() << "\n";
        facetlight::cli::abortOtherRanks(1);
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "facetlight: internal error: " << e.what() << "\n";
        facetlight::cli::abortOtherRanks(2);
        return 2;
    }
    return 0;
}
