#pragma once

#include <cstdint>

namespace collido::ode {

/// Most contacts one dCollide call can return: its capacity is the low 16 bits of `flags`
/// (ODE's NUMC_MASK). A capacity of 65,536 reads as 0, fails a user assertion and ODE aborts the
/// process, so the plugin never asks for more than this and reports the query as truncated when
/// the buffer fills.
inline constexpr std::uint64_t kMaxContactsPerCall = 0xffff;

/// Messages (ODE's dMessage: warnings such as "Trimesh-trimesh contach hash table bucket
/// overflow") that ODE sent on the calling thread since it started. The plugin's handler counts
/// them instead of printing them, so they do not distort timings; ODE calls the handler on the
/// thread that runs dCollide, so the difference of this figure across a query is that query's
/// count. Only reachable where the plugin is linked in (tests, tools), not through the C ABI.
std::uint64_t odeMessagesOnThisThread();

/// The same count over all threads since the plugin set its handler.
std::uint64_t odeMessagesTotal();

/// The format string of the latest message ("" when none came), unformatted: formatting would
/// cost more than the count itself, and a dense query can send millions.
const char* lastOdeMessageFormat();

}  // namespace collido::ode
