// Game-ready downloads of the tree page (issue 17 item 4): a triangle budget field, a budgeted
// .glb, an LOD .glb (tree_LOD0..2) and the wind sway as an animated .glb, all made by the worker
// (core/render/tree_lod, core/sway/sway_gltf through TreeSession), and the line of an export the
// worker refused (the page budget's estimate, issue 16) beside the button that asked for it.
// Does not: grow, draw, estimate, or know the state; the page hands it requestExport(format, fields).

const MIN_TRIANGLES = 6; // core/render/tree_lod.h kMinLodTriangles
const MAX_TRIANGLES = 100000000;

// The budget field's value: a whole number in range, or null with the one-line reason.
export function readBudget(text) {
  const t = String(text ?? '').trim();
  if (t === '') return { value: null, error: 'triangle budget: empty; must be a whole number in [6, 100000000]' };
  if (!/^\d+$/.test(t) || Number(t) < MIN_TRIANGLES || Number(t) > MAX_TRIANGLES) {
    return { value: null, error: `triangle budget: '${t.slice(0, 20)}' must be a whole number in [6, 100000000]` };
  }
  return { value: Number(t), error: '' };
}

// Builds the panel after `anchor` (the page's export buttons) and wires it to requestExport.
export function mountExportPanel(anchor, requestExport) {
  const box = document.createElement('div');
  box.className = 'export-panel';
  box.id = 'export-panel';
  box.innerHTML = `
    <label for="export-max-triangles">Triangle budget (game-ready .glb)</label>
    <input id="export-max-triangles" type="text" inputmode="numeric" value="20000"
      aria-describedby="export-budget-help export-budget-error">
    <p id="export-budget-help" class="help-text">Thin branches become cards or 3-sided twig cones
      (the thinnest are left out) and leaves leaf-cluster cards until the tree fits. LOD: levels tree_LOD0, _LOD1 (at most 25 %) and _LOD2 (5 %),
      the names Unity's importer groups into an LOD Group.</p>
    <p id="export-budget-error" class="field-error" role="alert"></p>
    <div class="buttons">
      <button id="download-budget-glb" type="button">Download budget .glb</button>
      <button id="download-lod-glb" type="button">Download LOD .glb</button>
      <button id="download-sway-glb" type="button">Download sway .glb</button>
    </div>
    <p id="export-refused" class="field-error" role="alert" hidden></p>`;
  anchor.after(box);
  const field = box.querySelector('#export-max-triangles');
  const error = box.querySelector('#export-budget-error');
  const budget = () => {
    const { value, error: line } = readBudget(field.value);
    error.textContent = line;
    field.setAttribute('aria-invalid', line ? 'true' : 'false');
    return value;
  };
  field.addEventListener('input', budget);
  box.querySelector('#download-budget-glb').addEventListener('click', () => {
    const maxTriangles = budget();
    if (maxTriangles !== null) requestExport('glb', { variant: 'budget', maxTriangles });
  });
  box.querySelector('#download-lod-glb').addEventListener('click', () => {
    const maxTriangles = budget();
    if (maxTriangles !== null) requestExport('glb', { variant: 'lod', maxTriangles });
  });
  box.querySelector('#download-sway-glb').addEventListener('click', () => {
    requestExport('glb', { variant: 'sway', fps: 30 });
  });
  return box;
}

// The buttons of each export variant (undefined: the page's own Download .glb).
const VARIANT_BUTTONS = { budget: 'download-budget-glb', lod: 'download-lod-glb', sway: 'download-sway-glb' };

// Where a refused export's line goes: under the export panel's buttons for its variants, else in a
// line made once right after the row holding #download-glb (`plainButton`). Returns
// {show(variant, line), clear()}; show() returns the id of the button the line is beside.
export function exportRefusals(panel, plainButton) {
  const panelLine = panel.querySelector('#export-refused');
  const plainLine = document.createElement('p');
  plainLine.id = 'glb-refused';
  plainLine.className = 'field-error';
  plainLine.setAttribute('role', 'alert');
  plainLine.hidden = true;
  (plainButton.closest('.buttons') || plainButton).after(plainLine);
  const lines = [panelLine, plainLine];
  const clear = () => {
    for (const line of lines) {
      line.textContent = '';
      line.hidden = true;
    }
  };
  return {
    clear,
    show(variant, text) {
      clear();
      const button = VARIANT_BUTTONS[variant] || plainButton.id;
      const line = VARIANT_BUTTONS[variant] ? panelLine : plainLine;
      line.textContent = text;
      line.hidden = false;
      document.getElementById(button)?.setAttribute('aria-describedby', line.id);
      return button;
    },
  };
}
