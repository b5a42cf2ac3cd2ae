#pragma once

#include <collido/runner/runner.h>

namespace collido::detail {

/// The kinds a backend is asked for `kinds`: with sub-steps (BackendSpec::substeps), a kind
/// over a step is answered from boolean answers.
QueryKindSet askedKinds(QueryKindSet kinds, int substeps);

/// Runs every query of `scene` on one backend setting and appends one measurement per query to
/// `report`: builds the objects, checks that the backend can answer each query (else a skipped
/// or failed measurement with the reason), steps through the frames with the observers the
/// scene and options call for, and times the calls by the options' protocol.
void runSceneOnBackend(const Scene& scene, const BackendSpec& spec, OracleCache& oracle,
                       OracleCache* finest_oracle, const RunOptions& options, RunReport& report);

}  // namespace collido::detail
