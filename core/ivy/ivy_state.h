// The one resolver of an ivy run's state (preset, seed, steps, parameters) from a state JSON (the
// page, --params FILE) or a share-link hash (the page, --url), bare keys on the ivy page and the
// "ivy." prefix on a composed page. Does not: grow (growth.h), pick the scene or seed points (the
// CLI and the page do), or parse parameter JSON itself (params/param_json).
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "base/status.h"
#include "ivy/ivy.h"
#include "ivy/ivy_params.h"

namespace niwa::ivy {

constexpr double kMaxIvySeed = 4294967295.0;
// The scene name of "a Niwa tree": its bark is grown by the caller (the CLI, the page's bindings:
// core/compose/ivy_on_tree) from tree and tree_years; core/ivy never includes core/tree.
constexpr const char* kTreeScene = "tree";
constexpr double kMaxTreeYears = 100;  // the tree study's kMaxYears (core/tree/tree.h)

struct IvyState {
  std::string preset = "paper";
  IvyParams params;  // the preset's values, then overrides
  uint64_t seed = 1;
  int steps = 50;
  // Where it grows, when the state says so (the page's share link; the CLI's --scene and
  // --seed-point win over these): a built-in scene name ("" = the caller's default) and seed points
  // in scene units (empty = the scene's first named seed).
  std::string scene;
  std::vector<glm::dvec3> seed_points;
  // Seed points given one by one (the CLI's --seed-point), each "X,Y,Z" or a named seed of the
  // support's scene ("base"): IvyRun resolves them in order against its support, in place of
  // seed_points (errors name "seed_points" and list the scene's names). Not in links or JSON: the
  // run's state holds the points they resolved to.
  std::vector<std::string> seed_point_items;
  // The support's geometry queries: "bvh" or "linear" (brute force); the support is prepared with
  // it (IvySupportOptions::For) and the run refuses one prepared otherwise. In the state JSON
  // only when linear; not in links.
  Accel accel = Accel::kBvh;
  // With scene == kTreeScene: the tree preset ("niwa presets tree") and its age in years. Only the
  // spelling is checked here; the caller that grows the tree names an unknown preset.
  std::string tree = "sakura";
  int tree_years = 10;
};

// Each setter checks its value and leaves the state unchanged on error (field: "preset", "seed",
// "steps"; the CLI renames it to its flag).
Status SetIvyPreset(std::string_view name, IvyState* state);  // resets params to the preset's
Status SetIvySeed(double seed, IvyState* state);              // whole number in [0, 4294967295]
Status SetIvySteps(double steps, IvyState* state);            // whole number in [0, 10000]
Status SetIvyScene(std::string_view name, IvyState* state);   // a built-in scene, "tree" or ""
// A tree preset's name: 1..40 of [a-z0-9_-] (the tree study checks that it exists).
Status SetIvyTree(std::string_view name, IvyState* state);
Status SetIvyTreeYears(double years, IvyState* state);       // whole number in [1, kMaxTreeYears]
Status SetIvyAccel(std::string_view name, IvyState* state);  // "bvh" or "linear"
// "X,Y,Z;X,Y,Z" (at most kMaxSeedPoints points, each coordinate in [-1e30, 1e30]); "" = none.
Status SetIvySeedPoints(std::string_view text, IvyState* state);
// The seed points as SetIvySeedPoints reads them (shortest round-trip numbers).
std::string FormatSeedPoints(const std::vector<glm::dvec3>& points);

// Applies {preset, seed, steps, scene, seed_points: "X,Y,Z;..", tree, tree_years, accel, params:
// {key: value}} (or the keys at the top level) onto state; a "preset" resets the parameters first.
// Strict: the first bad field is the error, state unchanged. The cross-row checks (t1 < t2, ...)
// are ValidateIvyParams's.
Status ApplyIvyStateJson(const std::string& text, IvyState* state);

// The state as JSON: {preset, seed, steps, scene, seed_points: "X,Y,Z;..", tree, tree_years,
// params: {key: value}}, which ApplyIvyStateJson reads back (one line).
std::string IvyStateJson(const IvyState& state);

// Applies "#preset=paper&seed=3&steps=50&scene=wall&at=0,10,10&t1=0.3" (keys prefixed with
// `prefix`, e.g. "ivy."); keys that are not the ivy's are skipped when `prefix` is non-empty (they
// belong to another study on a composed page) and dropped with a notice otherwise; bad values are
// clamped or dropped with a notice (notices are printable one-liners).
void ApplyIvyHash(std::string_view hash, std::string_view prefix, IvyState* state,
                  std::vector<std::string>* notices);
// The hash of a state: preset, seed, steps, scene and at (when set), tree and tree_years (on the
// tree scene), and every parameter that differs from the preset (not accel: a link grows the
// same ivy either way, and the page prepares its supports with a BVH).
std::string EncodeIvyHash(const IvyState& state, std::string_view prefix = "");

}  // namespace niwa::ivy
