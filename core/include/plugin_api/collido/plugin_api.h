/* The C boundary between Collidoscope and a backend plugin.
 *
 * A plugin is a shared library that exports one function, COLLIDO_PLUGIN_ENTRY_SYMBOL, returning a
 * pointer to a static CollidoPluginTable. The host reads abi_version first and refuses the plugin
 * when it differs from COLLIDO_PLUGIN_ABI_VERSION, so every other field may change between
 * versions. Nothing but plain C data crosses this boundary: no exceptions, no C++ types, no
 * ownership transfer. Plugin authors normally do not write against this header directly; they
 * implement collido::Backend (backend.h) and add one COLLIDO_DEFINE_PLUGIN line (plugin_export.h).
 *
 * Conventions (they hold for every function below):
 * - Every function returns a CollidoStatusCode; on anything but COLLIDO_STATUS_OK it writes a
 *   human-readable, NUL-terminated reason into the caller's CollidoMessage.
 * - Model handles are opaque 64-bit values; 0 is never a valid handle. A handle that was released,
 *   or never issued, yields COLLIDO_STATUS_INVALID_HANDLE, never a crash.
 * - Input arrays are valid only during the call; a plugin copies what it keeps.
 * - Output arrays (pairs, contacts, notes) belong to the backend instance and stay valid until the
 *   next call on that instance.
 * - Lengths are metres or whatever unit the scene uses; nothing here assumes a unit.
 */
#ifndef COLLIDO_PLUGIN_API_H
#define COLLIDO_PLUGIN_API_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/** The interface version; bump it on any change to the structures or functions below. */
#define COLLIDO_PLUGIN_ABI_VERSION 6u

/** The one symbol a plugin shared library exports. */
#define COLLIDO_PLUGIN_ENTRY_SYMBOL "collido_plugin_table"

/** Outcome of a call across the boundary. */
typedef enum CollidoStatusCode {
  COLLIDO_STATUS_OK = 0,
  COLLIDO_STATUS_UNSUPPORTED = 1,      /**< the backend cannot answer this (capabilities say so) */
  COLLIDO_STATUS_INVALID_ARGUMENT = 2, /**< malformed input: sizes, options, non-finite values */
  COLLIDO_STATUS_INVALID_HANDLE = 3,   /**< unknown, released or stale model handle */
  COLLIDO_STATUS_ENGINE_FAILURE = 4,   /**< the engine threw or reported an error */
  COLLIDO_STATUS_OUT_OF_MEMORY = 5,
  COLLIDO_STATUS_INTERNAL = 6 /**< a bug in the plugin or adapter */
} CollidoStatusCode;

/** Bit flags naming the questions a query can ask. */
typedef enum CollidoQueryKind {
  COLLIDO_QUERY_BOOLEAN = 1u << 0,   /**< do the two shapes share a point? (early exit allowed) */
  COLLIDO_QUERY_ALL_PAIRS = 1u << 1, /**< every intersecting (triangle of A, triangle of B) pair */
  COLLIDO_QUERY_CONTACTS = 1u << 2,  /**< contact points with normal and depth */
  COLLIDO_QUERY_DISTANCE = 1u << 3,  /**< the distance between the shapes, with closest points */
  COLLIDO_QUERY_FIRST_CONTACT = 1u << 4 /**< when the shapes first touch as they move over a step */
} CollidoQueryKind;

/** Bit flags naming the shape kinds a backend can build. */
typedef enum CollidoShapeKind {
  COLLIDO_SHAPE_TRIANGLE_MESH = 1u << 0,
  COLLIDO_SHAPE_NURBS_SURFACE = 1u << 1
} CollidoShapeKind;

/** Bit flags for what a backend can do beyond answering queries. */
typedef enum CollidoFeature {
  COLLIDO_FEATURE_UPDATE = 1u << 0,          /**< update() accepts new vertex positions */
  COLLIDO_FEATURE_COUNTS_BV_TESTS = 1u << 1, /**< results carry bounding-volume test counts */
  COLLIDO_FEATURE_COUNTS_PRIMITIVE_TESTS = 1u << 2, /**< results carry primitive test counts */
  COLLIDO_FEATURE_COUNTS_UPDATE_WORK = 1u << 3 /**< update() reports the volumes it refit/rebuilt */
} CollidoFeature;

/** Bit flags of CollidoBuildNeeds::flags. */
typedef enum CollidoNeedFlag {
  COLLIDO_NEED_DEFORMS = 1u << 0 /**< update() will be called on this model */
} CollidoNeedFlag;

/** A reason written by the callee, always NUL-terminated. */
typedef struct CollidoMessage {
  char text[1024];
} CollidoMessage;

/** A key/value option given to create(), e.g. {"max_leaf_triangles", "4"}. */
typedef struct CollidoOption {
  const char* key;
  const char* value;
} CollidoOption;

/** One backend variant offered by a plugin, e.g. "fcl:obb". */
typedef struct CollidoVariantInfo {
  const char* name;    /**< unique among all plugins; "engine" or "engine:flavour" */
  const char* summary; /**< one line for `collido backends` */
} CollidoVariantInfo;

/** What an instance can do. */
typedef struct CollidoCapabilities {
  uint32_t shape_kinds;  /**< CollidoShapeKind bits */
  uint32_t query_kinds;  /**< CollidoQueryKind bits */
  uint32_t features;     /**< CollidoFeature bits */
  uint32_t reserved;     /**< zero */
  uint64_t max_contacts; /**< most contacts one query can return; 0 = no limit */
  const char* notes;     /**< limits worth knowing, one paragraph; may be "" */
} CollidoCapabilities;

/** A triangle mesh in its model frame. */
typedef struct CollidoTriangleMeshView {
  const double* positions; /**< 3 * vertex_count doubles, x y z per vertex */
  uint32_t vertex_count;
  uint32_t triangle_count;
  const int32_t* triangles; /**< 3 * triangle_count vertex indices, counter-clockwise = outward */
} CollidoTriangleMeshView;

/** A NURBS surface in its model frame: degrees p, q; clamped knot vectors; a net of
 *  count_u x count_v homogeneous control points (w x, w y, w z, w), the u index outermost. */
typedef struct CollidoNurbsSurfaceView {
  uint32_t degree_u;     /**< p >= 1 */
  uint32_t degree_v;     /**< q >= 1 */
  uint32_t count_u;      /**< control points along u, > p */
  uint32_t count_v;      /**< control points along v, > q */
  const double* knots_u; /**< count_u + p + 1 values, non-decreasing */
  const double* knots_v; /**< count_v + q + 1 values, non-decreasing */
  const double* control; /**< 4 * count_u * count_v doubles; control[4 * (i * count_v + j)] */
} CollidoNurbsSurfaceView;

/** A shape to build; `kind` says which pointer is set. */
typedef struct CollidoShapeView {
  uint32_t kind; /**< one CollidoShapeKind value */
  uint32_t reserved;
  const CollidoTriangleMeshView* mesh;    /**< set when kind == COLLIDO_SHAPE_TRIANGLE_MESH */
  const CollidoNurbsSurfaceView* surface; /**< set when kind == COLLIDO_SHAPE_NURBS_SURFACE */
} CollidoShapeView;

/** A model handle; 0 is never valid. */
typedef uint64_t CollidoModelHandle;

/** What the scene will ask of a model, so the backend builds only that. */
typedef struct CollidoBuildNeeds {
  uint32_t query_kinds; /**< CollidoQueryKind bits the model will be queried with */
  uint32_t flags;       /**< CollidoNeedFlag bits */
  /** Another active state of the same object, or 0: a live model of this instance built from a
   *  mesh with the same vertex count and the same triangle list (same order). The backend may
   *  share with it whatever does not depend on vertex positions; the host never releases it
   *  before this model's last use, but the backend must not rely on it outliving this model. */
  CollidoModelHandle state_of;
  /** CollidoQueryKind bits asked anywhere among the objects linked to this one through queries
   *  (directly or through others), or 0 when the host does not say. A backend whose model type
   *  depends on the kinds picks it by these bits, so the two models of every pair it is asked
   *  about are of one type. (Added in interface version 5.) */
  uint32_t linked_query_kinds;
} CollidoBuildNeeds;

/** A rigid transform: world = rotation * model + translation. */
typedef struct CollidoPose {
  double rotation[9]; /**< row-major 3x3 */
  double translation[3];
} CollidoPose;

/** The question asked of one pair of models. */
typedef struct CollidoQueryRequest {
  uint32_t kind;         /**< exactly one CollidoQueryKind value */
  uint32_t reserved;     /**< zero */
  uint64_t max_pairs;    /**< ALL_PAIRS: stop after this many pairs; 0 = no limit */
  uint64_t max_contacts; /**< CONTACTS: stop after this many contacts; 0 = no limit */
  /** DISTANCE: the answer may exceed the true distance d by at most
   *  max(abs_tolerance, rel_tolerance * d) (beyond rounding); both 0 = as exact as the backend
   *  can. Finite and >= 0. */
  double abs_tolerance;
  double rel_tolerance;
  /** FIRST_CONTACT: the poses of A and B at the step's end (the query's poses are its start);
   *  each object's origin moves on the line between its two poses and it turns at a constant
   *  rate about one fixed axis through its origin (collido::StepMotion). Rigid. */
  CollidoPose end_a;
  CollidoPose end_b;
  double bracket_width; /**< FIRST_CONTACT: the widest bracket of the first contact, > 0 */
} CollidoQueryRequest;

/** An intersecting pair: triangle index in A, triangle index in B (as given to build). */
typedef struct CollidoTrianglePair {
  int32_t a;
  int32_t b;
} CollidoTrianglePair;

/** A contact, in the world frame. */
typedef struct CollidoContact {
  double position[3]; /**< a point of the contact region */
  double normal[3];   /**< unit; points from A towards B (moving B along it separates) */
  double depth;       /**< penetration depth along normal, >= 0 */
  int32_t triangle_a; /**< -1 when the engine does not say */
  int32_t triangle_b; /**< -1 when the engine does not say */
} CollidoContact;

/** The answer to a DISTANCE query, in the world frame. The distance is 0 when the shapes share
 *  a point; otherwise it is |point_b - point_a|, the points lying on A and on B. */
typedef struct CollidoDistance {
  double distance;
  double point_a[3];   /**< on A (on the reported triangle when triangle_a >= 0) */
  double point_b[3];   /**< on B */
  double lower;        /**< a certified lower bound on the true distance; valid with has_bounds */
  double upper;        /**< a certified upper bound; valid with has_bounds */
  double params_a[2];  /**< (u, v) of point_a on a NURBS surface A; valid with has_params */
  double params_b[2];  /**< (u, v) of point_b on a NURBS surface B; valid with has_params */
  int32_t triangle_a;  /**< triangle of A holding point_a, or -1 when the engine does not say */
  int32_t triangle_b;  /**< triangle of B holding point_b, or -1 */
  uint32_t has_bounds; /**< 1 when [lower, upper] is certified by the backend */
  uint32_t has_params; /**< 1 when params_a and params_b are set (both shapes are surfaces) */
} CollidoDistance;

/** The answer to a FIRST_CONTACT query, t in [0, 1] along the step. */
typedef struct CollidoFirstContact {
  uint32_t touches;   /**< 1 when the shapes share a point at some t of the step */
  uint32_t reserved;  /**< zero */
  double t_lo;        /**< touches: no shared point before t_lo */
  double t_hi;        /**< touches: a shared point at t_hi; t_lo <= t_hi <= t_lo + bracket_width */
  int32_t triangle_a; /**< a pair touching at t_hi, or -1 when the engine does not say */
  int32_t triangle_b;
} CollidoFirstContact;

/** Work the backend did for one query; fields are valid only where `counted` has the bit. */
typedef struct CollidoWorkCounters {
  uint64_t bv_tests;        /**< bounding-volume overlap tests */
  uint64_t primitive_tests; /**< triangle-triangle (or primitive) tests */
  uint32_t counted;         /**< CollidoFeature COUNTS_* bits that apply */
  uint32_t reserved;
} CollidoWorkCounters;

/** The answer to one query. Arrays belong to the instance (see the conventions above). */
typedef struct CollidoQueryResult {
  uint32_t intersecting; /**< 1 if the shapes share at least one point */
  uint32_t truncated;    /**< 1 if a limit stopped the query before the full answer */
  const CollidoTrianglePair* pairs;
  uint64_t pair_count;
  const CollidoContact* contacts;
  uint64_t contact_count;
  CollidoDistance distance;          /**< DISTANCE queries only */
  CollidoFirstContact first_contact; /**< FIRST_CONTACT queries only */
  CollidoWorkCounters counters;
} CollidoQueryResult;

/** Work one update() did; the fields are valid only when `counted` is 1. */
typedef struct CollidoUpdateCounters {
  uint64_t nodes_refit;   /**< bounding volumes measured anew, the structure kept */
  uint64_t rebuilds;      /**< structures rebuilt from scratch (whole models or subtrees) */
  uint64_t nodes_rebuilt; /**< bounding volumes in those rebuilt structures */
  uint32_t counted;       /**< 1 when the backend counted (COLLIDO_FEATURE_COUNTS_UPDATE_WORK) */
  uint32_t reserved;
} CollidoUpdateCounters;

/** An opaque backend instance, created by CollidoPluginTable::create. */
typedef struct CollidoInstance CollidoInstance;

/** The table a plugin exports. The first two fields never move. */
typedef struct CollidoPluginTable {
  uint32_t abi_version; /**< COLLIDO_PLUGIN_ABI_VERSION the plugin was built with */
  uint32_t struct_size; /**< sizeof(CollidoPluginTable) as the plugin saw it */
  const char* plugin_name;
  const char* plugin_version;
  const char* engine_name;
  const char* engine_version;
  uint32_t variant_count;
  uint32_t reserved;
  const CollidoVariantInfo* variants;

  int32_t (*create)(const char* variant, const CollidoOption* options, uint32_t option_count,
                    CollidoInstance** out, CollidoMessage* error);
  void (*destroy)(CollidoInstance* instance);
  int32_t (*capabilities)(CollidoInstance* instance, CollidoCapabilities* out,
                          CollidoMessage* error);
  int32_t (*build)(CollidoInstance* instance, const CollidoShapeView* shape,
                   const CollidoBuildNeeds* needs, CollidoModelHandle* out, CollidoMessage* error);
  int32_t (*update)(CollidoInstance* instance, CollidoModelHandle model, const double* positions,
                    uint32_t vertex_count, CollidoUpdateCounters* out, CollidoMessage* error);
  int32_t (*query)(CollidoInstance* instance, CollidoModelHandle a, const CollidoPose* pose_a,
                   CollidoModelHandle b, const CollidoPose* pose_b,
                   const CollidoQueryRequest* request, CollidoQueryResult* out,
                   CollidoMessage* error);
  int32_t (*memory)(CollidoInstance* instance, CollidoModelHandle model, uint64_t* bytes,
                    CollidoMessage* error);
  int32_t (*release)(CollidoInstance* instance, CollidoModelHandle model, CollidoMessage* error);
} CollidoPluginTable;

/** Signature of the exported entry point. */
typedef const CollidoPluginTable* (*CollidoPluginEntry)(void);

#ifdef __cplusplus
}
#endif

#endif /* COLLIDO_PLUGIN_API_H */
