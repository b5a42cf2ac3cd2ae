#pragma once

#include <stddef.h>  // NOLINT(modernize-deprecated-headers): also read as C
#include <stdint.h>  // NOLINT(modernize-deprecated-headers): also read as C

// The C interface of OpenVDB's volume-to-mesh as a loadable module (core/openvdb_mesher/), which
// polygonize.cpp opens on first use: linking OpenVDB into every process cost each `collido` start
// about 58 ms of symbol relocations, for the few runs that polygonize anything. The entry point's
// name carries the interface version, so a module of another version is not found rather than
// misread.
#ifdef __cplusplus
extern "C" {
#endif

/// One polygonization: a grid of `counts` cubic cells of side `cell`, its level set sampled
/// through `level` (OpenVDB's sign: negative inside), and the mesh handed back vertex by vertex
/// (in the grid's frame: index times the cell) and polygon by polygon (3 or 4 corners, counter-
/// clockwise seen from outside).
typedef struct CollidoMesherRequest {
  double cell;
  int32_t counts[3];
  float (*level)(void* context, int32_t i, int32_t j, int32_t k);
  void* level_context;
  void (*vertex)(void* context, double x, double y, double z);
  void (*polygon)(void* context, const uint32_t* corners, int32_t corner_count);
  void* mesh_context;
} CollidoMesherRequest;

/// Runs the request; 0 on success, else nonzero with the reason in `error` (always terminated).
typedef int (*CollidoMesherRun)(const CollidoMesherRequest* request, char* error,
                                size_t error_size);

#define COLLIDO_OPENVDB_MESHER_ENTRY "collido_openvdb_mesher_v1"

#ifdef __cplusplus
}
#endif
