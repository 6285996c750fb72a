// The tree page's dock on a phone (issue 32 item 4): on a view as narrow as style.css's one-column
// layout (max-width 760 px, or a tablet held upright: portrait up to 1,100 px wide; the panel goes
// under the view), the controls used most (Preset, Age,
// Blow, Cut and Undo, with the line saying what is selected) move into the dock right under the view,
// so each one's effect shows on the same screen as the control (they sat 1,868-2,945 px down the
// panel); on a wider view they go back to their places in the panel. Play is in the view already.
// The elements themselves move (their ids, labels, listeners and error lines go with them): one
// control, one place; a comment left where each stood marks its way back.
// Does not: create or wire a control, or style the dock (style.css `.dock`).
import { setHooks } from '../shell/test_hooks.js';

// Keep in step with style.css's one-column @media rule.
export const PHONE_QUERY = '(max-width: 760px), (orientation: portrait) and (max-width: 1100px)';

export class PhoneDock {
  // dock: the element under the view, holding slots [data-dock-slot=NAME]; query: the media query
  // of the one-column layout.
  constructor(dock, query = PHONE_QUERY) {
    this.dock = dock;
    this.items = [];  // {element, mark (the comment where it stood), slot}
    this.media = window.matchMedia(query);
    this.media.addEventListener('change', () => this.apply());
  }

  // Adds elements (in order) to the dock's slot `slot`; those missing are skipped.
  add(slot, ...elements) {
    for (const element of elements) {
      if (!element || this.items.some((item) => item.element === element)) continue;
      const mark = document.createComment(`dock: ${element.id || element.className || element.tagName}`);
      element.before(mark);
      this.items.push({ element, mark, slot });
    }
    this.apply();
    return this;
  }

  // Whether the controls are in the dock now.
  get docked() {
    return this.media.matches;
  }

  apply() {
    const docked = this.media.matches;
    for (const { element, mark, slot } of this.items) {
      // (an element already in its place stays put: a move would take its focus away)
      const home = docked ? this.dock.querySelector(`[data-dock-slot="${slot}"]`) : null;
      if (docked && home && element.parentElement !== home) home.append(element);
      else if (!docked && element.previousSibling !== mark) mark.after(element);
    }
    this.dock.hidden = !docked || this.items.length === 0;
    setHooks({ docked: docked ? 1 : 0 });  // tests
  }
}
