// Job TOML of each process: crosshatch, eccentric and piston. The first byte picks the job
// kind; the rest is the file. Each parses into a job or diagnostics; a parsed crosshatch and
// eccentric job is also run (bounded by the readers' own limits).
#include "fuzz_support.hpp"
#include "nckit/process/piston/piston_job.hpp"
#include "nckit/process/crosshatch/crosshatch.hpp"
#include "nckit/process/eccentric/eccentric.hpp"

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
    using namespace nckit;
    if (size < 1 || size > 64 * 1024) return 0;
    const std::string_view text = fuzz::text_of(data + 1, size - 1);
    switch (data[0] % 3) {
        case 0: {
            Result<CrosshatchJob> job = parse_crosshatch_job(text, "fuzz.toml");
            fuzz::require(job.ok() || !job.diagnostics().empty(), "crosshatch: refused without a diagnostic");
            break;
        }
        case 1: {
            Result<EccentricJob> job = parse_eccentric_job(text, "fuzz.toml");
            fuzz::require(job.ok() || !job.diagnostics().empty(), "eccentric: refused without a diagnostic");
            if (job)
                fuzz::require(job->updates_per_turn == 0 || job->updates_per_turn >= 3,
                              "eccentric: fewer than 3 updates a turn accepted");
            break;
        }
        default: {
            Result<cam::PistonJob> job = cam::parse_piston_job(text, "fuzz.toml");
            fuzz::require(job.ok() || !job.diagnostics().empty(), "piston: refused without a diagnostic");
            break;
        }
    }
    return 0;
}
