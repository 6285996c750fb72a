// The tree page's guards against edits and downloads that make no sense (issue 17 item 6):
// cutting the trunk is refused, and a .glb of a tree with nothing in it is not offered.
// The trunk (branch 0, the seedling's first shoot) carries every other branch: a prune of it
// removes the whole tree after that year and leaves an empty model, which no user wants by a
// single click or Delete key, and the same tree is reached by lowering Years. So the page refuses
// it (rather than asking) and says what to do instead; a hash that carries such a prune still
// grows (the core accepts it), and then the download is disabled with the reason shown.
// Does not: prune (the core does), or know the mesh layout beyond index counts.

export const TRUNK = 0;

// '' when branch `id` may be cut at year `year`, else the line that says why not.
export function cutRefusal(id, year) {
  if (!Number.isInteger(id)) return 'Select a branch first: click or tap it in the view.';
  if (!(year >= 1)) return 'Nothing to cut yet: the tree is in its first year.';
  if (id === TRUNK) {
    return 'The trunk cannot be cut: it carries the whole tree, so the cut would leave nothing. '
      + 'Select a branch above it, or lower Years for a younger tree.';
  }
  return '';
}

// Triangles of a page mesh ({bark|leaves|flowers: {indices}}).
export function meshTriangles(mesh) {
  let n = 0;
  for (const part of Object.values(mesh || {})) n += part?.indices ? part.indices.byteLength / 12 : 0;
  return n;
}

// Keeps the .glb button disabled, with its reason shown beside it, while the tree is empty.
export class ExportGuard {
  constructor(button) {
    this.button = button;
    this.reason = document.createElement('p');
    this.reason.id = 'glb-reason';
    this.reason.className = 'help-text';
    this.reason.hidden = true;
    button.setAttribute('aria-describedby', this.reason.id);
    (button.closest('.buttons') || button).after(this.reason);
    this.empty = true;
    this.set(true, 'The .glb download waits for the first tree.');
  }

  set(empty, why) {
    this.empty = empty;
    this.button.disabled = empty;
    this.reason.textContent = empty ? why : '';
    this.reason.hidden = !empty;
    document.documentElement.dataset.glbOffered = empty ? '0' : '1';
  }

  // A new tree is on screen: its stats (internodes) and mesh.
  update(stats, mesh) {
    const triangles = meshTriangles(mesh);
    if (!stats || stats.internodes === 0 || triangles === 0) {
      this.set(true, 'Download .glb is off: this tree is empty (no branches, leaves or flowers), '
        + 'so the file would hold no model. Undo the cut or grow more years.');
    } else {
      this.set(false, '');
    }
  }
}
