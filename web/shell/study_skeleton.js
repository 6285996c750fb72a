// The one HTML skeleton of a study page: the view (canvas, timeline, the progress box with Cancel
// first and the stats line under it) and the panel's head (title, tagline, studies nav, notices),
// written once here and filled into the page's placeholders before the page module runs (each
// page module imports this module first, so its `document.getElementById` calls find the parts).
// A page's HTML keeps only what is its own: `<section class="stage" data-skeleton="stage" ...>`
// and `<header data-skeleton="head" ...>` with data-* saying what differs, then its own controls.
// Does not: wire any behaviour (web/shell/study_controller.js, the page module), or style (style.css).

const esc = (text) => String(text).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);

// The view: data-view-label (the canvas's aria-label), data-step ("Step": the timeline's label;
// its range is #<data-step-id>, its text #<data-step-id>-text, max data-step-max), data-work (what
// Cancel goes back to: "ivy"), data-progress-id (a <progress> bar's id, or none), data-loading (the
// stats line at first), data-frame-stats (present: a #frame-stats span after the stats).
export function stageHtml(d) {
  const id = d.stepId || 'step';
  return `
      <canvas id="view" tabindex="0" aria-label="${esc(d.viewLabel || '3D view')}"></canvas>
      <div class="timeline">
        <button id="play" type="button" aria-pressed="false">Play</button>
        <label for="${esc(id)}">${esc(d.step || 'Step')}</label>
        <input id="${esc(id)}" type="range" min="0" max="${esc(d.stepMax || '10')}" step="1" value="${esc(d.stepMax || '10')}" aria-describedby="${esc(id)}-text">
        <output id="${esc(id)}-text" for="${esc(id)}" class="year-text"></output>
      </div>
      <div class="view-foot">
        <div class="progress-box">
          <button id="cancel" type="button" hidden title="Stop this work at once and go back to the last finished ${esc(d.work || 'result')}">Cancel</button>
          ${d.progressId ? `<progress id="${esc(d.progressId)}" max="1" value="0" aria-label="${esc(d.progressLabel || 'Progress')}" hidden></progress>` : ''}
          <p id="progress" class="progress" aria-live="polite"></p>
        </div>
        <p class="stats"><span id="stats" aria-live="polite">${esc(d.loading || 'loading…')}</span>${d.frameStats !== undefined ? '<span id="frame-stats" class="frame-stats"></span>' : ''}</p>
      </div>`;
}

// The panel's head: data-title, data-tagline (may hold &amp; as text: it is escaped here).
export function headHtml(d) {
  return `
        <h1>${esc(d.title || 'Niwa')}</h1>
        <p class="tagline">${esc(d.tagline || '')}</p>
        <nav id="studies" class="studies" aria-label="Studies"></nav>`;
}

// Fills every [data-skeleton] placeholder of `root` once; a head is followed by the notices box.
export function mountSkeleton(root = document) {
  for (const el of root.querySelectorAll('[data-skeleton]')) {
    if (el.dataset.mounted) continue;
    if (el.dataset.skeleton === 'stage') el.insertAdjacentHTML('afterbegin', stageHtml(el.dataset));
    if (el.dataset.skeleton === 'head') {
      el.innerHTML = headHtml(el.dataset);
      el.insertAdjacentHTML('afterend', '<div id="notice" class="notice" role="status" aria-live="polite" hidden></div>');
    }
    el.dataset.mounted = '1';
  }
}

if (typeof document !== 'undefined') mountSkeleton();
