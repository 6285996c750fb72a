// The shell every study page shares: the header nav linking the studies' pages, the notices box
// (text only, never markup: notices may echo the URL), the share line, downloads, Copy link and
// the embed dialog. A study page module wires only its own controls on top of these.
// Does not: talk to the worker, keep history (hash_history.js), or draw (web/gl, web/<study>).

// The studies' pages, in nav order: the ONE list of them (the five papers' studies, the grove and the garden).
// The tree and grove pages always exist; the others are linked once public/ holds their page, which
// the build lists in wasm/studies.json (web/CMakeLists.txt), so adding a study's page needs no edit here.
export const STUDIES = [
  { id: 'tree', title: 'Tree', page: 'index.html', always: true },
  { id: 'grove', title: 'Grove', page: 'grove.html', always: true },
  { id: 'ivy', title: 'Ivy', page: 'ivy.html' },
  { id: 'terrain', title: 'Terrain', page: 'terrain.html' },
  { id: 'moss', title: 'Moss', page: 'moss.html' },
  { id: 'bark', title: 'Bark', page: 'bark.html' },
  { id: 'garden', title: 'Garden', page: 'garden.html' },
];

const PAGES_URL = new URL('../../wasm/studies.json', import.meta.url);

async function servedPages() {
  try {
    const response = await fetch(PAGES_URL, { cache: 'no-cache' });
    const list = response.ok ? (await response.json()).pages : [];
    return new Set(Array.isArray(list) ? list : []);
  } catch {
    return new Set();
  }
}

// Fills `nav` (a <nav> element) with links to the studies' pages that exist; `current` (a study
// id) is marked aria-current. Links are relative to the page's folder (public/). Resolves once the
// nav is complete.
export async function mountStudyNav(nav, current) {
  if (!nav) return;
  const list = document.createElement('ul');
  const draw = (shown) => {
    list.replaceChildren();
    for (const study of STUDIES.filter((s) => shown.has(s.id))) {
      const item = document.createElement('li');
      const link = document.createElement('a');
      link.href = study.page === 'index.html' ? './' : study.page;
      link.textContent = study.title;
      if (study.id === current) link.setAttribute('aria-current', 'page');
      item.append(link);
      list.append(item);
    }
  };
  const shown = new Set(STUDIES.filter((s) => s.always || s.id === current).map((s) => s.id));
  draw(shown);
  nav.replaceChildren(list);
  const pages = await servedPages();
  for (const s of STUDIES) if (pages.has(s.page)) shown.add(s.id);
  draw(shown);
}

// Most notice lines shown at once; the rest are counted in one "... N more" line (a hostile hash
// can carry thousands of bad keys).
export const MAX_NOTICE_LINES = 5;
// Longest notice line shown, in characters, before "..." (the core already cuts echoed values).
export const MAX_NOTICE_CHARS = 300;

// The lines shown for `lines`: control characters as \xNN, each cut at MAX_NOTICE_CHARS, at most
// MAX_NOTICE_LINES and then "... N more".
export function cappedNoticeLines(lines) {
  const clean = lines.map((line) => {
    // eslint-disable-next-line no-control-regex
    const text = line.replace(/[\u0000-\u001f\u007f-\u009f]/g,
      (c) => `\\x${c.charCodeAt(0).toString(16).padStart(2, '0')}`);
    return text.length > MAX_NOTICE_CHARS ? `${text.slice(0, MAX_NOTICE_CHARS)}...` : text;
  });
  if (clean.length <= MAX_NOTICE_LINES) return clean;
  return [...clean.slice(0, MAX_NOTICE_LINES), `... ${clean.length - MAX_NOTICE_LINES} more`];
}

// Named sources of notice lines shown together in one element (textContent only, capped by
// cappedNoticeLines).
export class Notices {
  constructor(element, order = []) {
    this.element = element;
    this.sources = new Map(order.map((name) => [name, []]));
  }

  // Replaces the lines of `source` (a string, an array of strings, or '' / [] for none).
  set(source, lines) {
    this.sources.set(source, (Array.isArray(lines) ? lines : [lines]).filter(Boolean).map(String));
    this.show();
  }

  show() {
    const lines = cappedNoticeLines([...this.sources.values()].flat());
    this.element.textContent = lines.join('\n');
    this.element.hidden = lines.length === 0;
  }
}

// Saves `blob` as `name` through a temporary link; says so on `status` (an element, optional).
export function download(blob, name, status) {
  const url = URL.createObjectURL(blob);
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
  if (status) status.textContent = `Saved ${name}`;
}

// Copies location.href to the clipboard, or shows it for copying by hand.
export async function copyLink(status) {
  try {
    await navigator.clipboard.writeText(location.href);
    status.textContent = 'Link copied.';
  } catch {
    status.textContent = `Copy this link: ${location.href}`;
  }
}

// The embed dialog (one per page, made on first use; ids embed-dialog, embed-element, embed-iframe).
function embedDialog(heading) {
  let dialog = document.getElementById('embed-dialog');
  if (!dialog) {
    dialog = document.createElement('dialog');
    dialog.id = 'embed-dialog';
    dialog.setAttribute('aria-labelledby', 'embed-title');
    dialog.innerHTML = `<h2 id="embed-title"></h2>
      <label for="embed-element">Custom element (load the script once per page)</label>
      <textarea id="embed-element" readonly rows="5"></textarea>
      <label for="embed-iframe">Or an iframe</label>
      <textarea id="embed-iframe" readonly rows="3"></textarea>
      <form method="dialog"><button type="submit">Close</button></form>`;
    document.body.append(dialog);
  }
  dialog.querySelector('#embed-title').textContent = heading;
  return { dialog, element: dialog.querySelector('#embed-element'), iframe: dialog.querySelector('#embed-iframe') };
}

// Opens the embed dialog with the custom-element and iframe snippets for the current hash.
// tag: the custom element (e.g. 'niwa-tree'); title: the iframe's title; heading: the dialog's;
// script: the element's module; frame: the iframe's page (both in public/).
export function showEmbedDialog({ tag, title, heading = 'Embed this view', script = 'niwa-embed.js', frame = 'embed.html' }) {
  const ui = embedDialog(heading);
  const base = new URL('.', location.href).href;
  const state = location.hash.slice(1).replace(/&/g, '&amp;').replace(/"/g, '&quot;');
  ui.element.value = `<script type="module" src="${base}${script}"></script>\n`
    + `<${tag} state="${state}" style="width:480px;height:360px"></${tag}>`;
  ui.iframe.value = `<iframe src="${base}${frame}#${state}" width="480" height="360" title="${title}" loading="lazy"></iframe>`;
  ui.dialog.showModal();
  ui.element.select();
}

// The stats line's frame cost: the mean CPU time of the last `size` frames drawn (frames are drawn
// on demand, so there is no steady frame rate to report; GPU time is not measurable here).
export class FrameTimes {
  constructor(size = 30) {
    this.size = size;
    this.times = [];
  }

  // Adds one frame's CPU ms; returns the mean over the kept frames.
  push(ms) {
    this.times.push(ms);
    if (this.times.length > this.size) this.times.shift();
    return this.times.reduce((a, b) => a + b, 0) / this.times.length;
  }

  get count() {
    return this.times.length;
  }
}
