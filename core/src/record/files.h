// The recording's files: atomic writes and the meshes as binary PLY, named by their content.
#pragma once

#include <string>

#include <Eigen/Core>

namespace collido::record {

/// Writes `bytes` to `path` through a temporary file renamed over it, so that a reader never
/// sees half a file; throws RecordError naming the path.
void writeFileAtomically(const std::string& path, const std::string& bytes);

/// A 128-bit digest of the mesh (two independent 64-bit hashes), as 32 hex digits: the mesh
/// file's name, so that identical meshes share one file.
std::string meshDigest(const Eigen::Matrix3Xd& vertices, const Eigen::Matrix3Xi& triangles);

/// The mesh as binary little-endian PLY: double vertices, int triangle indices.
std::string plyBytes(const Eigen::Matrix3Xd& vertices, const Eigen::Matrix3Xi& triangles);

}  // namespace collido::record
