// The one place that writes the data-* attributes the browser tests read (tests/browser/*.mjs):
// page state on <html> (status, treeSerial, year, renderViews, swayTime, ...) and per element
// (each <niwa-tree>'s own status and counts). Attribute names are part of the test contract.
// Does not: read anything for the page's own logic except counters it keeps itself.

const root = document.documentElement;

// Sets data-* of `element` (default <html>) from {camelCaseName: value}; values become strings.
export function setHooks(fields, element = root) {
  for (const [key, value] of Object.entries(fields)) element.dataset[key] = value === null || value === undefined ? '' : String(value);
}

// Adds `by` to the numeric data-<key> of `element` and returns the new value.
export function bumpHook(key, element = root, by = 1) {
  const next = Number(element.dataset[key] || 0) + by;
  element.dataset[key] = String(next);
  return next;
}

// The current value of data-<key> (for hooks derived from other hooks, as drawnViewSerial).
export function hookValue(key, element = root) {
  return element.dataset[key];
}
