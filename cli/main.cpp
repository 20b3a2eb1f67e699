// facetlight: the command-line face of the photon-mapping core.
#include <iostream>

#include "commands.h"
#include "process_communicator.h"
#include "util/error.h"
#include "util/simd_target.h"

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
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
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
