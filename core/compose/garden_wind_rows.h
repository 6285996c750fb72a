// The garden's wind settings (Blow's; issue 33 item 6, docs/garden-model.md "Blow"): which rows of
// the tree table's "wind" group (niwa params tree, group wind: the one table of the wind's rows) a
// garden state carries, the garden's defaults over the table's, and the rows a Blow runs with
// (gust_on derived from the garden's size, so the front enters the garden as Blow is pressed).
// Does not: read or write a whole state's JSON or link (garden_state), or sway anything
// (garden_wind).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "base/status.h"
#include "params/param_table.h"
#include "tree/tree_params.h"

namespace niwa::compose {

// The garden's wind before a state's own rows: the grove page's (web/tree/grove_page.js WIND),
// rows of the tree table's "wind" group: 8 m/s towards +x, a gust front at 4 m/s, a ±40 % wave
// 25 m long every 5 s, for 600 s.
struct GardenWindValue {
  const char* key;
  double value;
};
const std::vector<GardenWindValue>& GardenWindDefaults();

// The tree table at its defaults with GardenWindDefaults over them: a default garden's wind.
TreeParams GardenWindBase();

// True for a row a garden state carries as its wind: every row of the tree table's "wind" group
// but gust_on (the garden derives it: GardenWindRows).
bool IsGardenWindKey(std::string_view key);
// The keys IsGardenWindKey accepts, in table order.
std::vector<std::string> GardenWindKeys();

// The wind rows (a tree-table ParamSet, only its "wind" group and dt read) of a Blow: the garden
// wind keys of `base` (a state's wind) over the table's defaults, then `json` ({"wind_speed": 5,
// ...}: keys of the tree table's "wind" group, gust_on included, each checked against its row; ""
// or "{}" for none). Without gust_on in `json`, gust_on is the time the front takes from the
// garden's upwind edge (a square of side `size` m about the origin) to the origin, so the gust
// enters the garden as the wind starts (0 when the front is instant). Errors name the key
// ("wind_speed", "gust_off") or "wind".
Result<ParamSet> GardenWindRows(double size, const ParamSet& base, const std::string& json);
// The same over GardenWindBase().
Result<ParamSet> GardenWindRows(double size, const std::string& json);

}  // namespace niwa::compose
