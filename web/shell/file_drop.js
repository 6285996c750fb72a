// A file drop zone any study page can reuse: dropping files on `target` (it gets the class
// 'dropping' while a drag is over it) or choosing them with a file input hands them to onFiles;
// names outside `accept` (lower-case extensions) are refused with one line for the page's notices.
// Does not: read or parse the files (the page decides what they are), or upload anything.

// Lower-case extension of a file name, with its dot ('.glb'), or ''.
export function extensionOf(name) {
  const m = /\.[^./\\]+$/.exec(String(name));
  return m ? m[0].toLowerCase() : '';
}

export class FileDrop {
  // target: element to drop on; input: an <input type="file"> (optional); accept: ['.glb', ...];
  // onFiles(files: File[]); onRefuse(line): a dropped name that is not accepted; what: the kind
  // of file named in that line.
  constructor({ target, input, accept, onFiles, onRefuse = () => {}, what = 'mesh file' }) {
    this.accept = accept.map((a) => a.toLowerCase());
    const take = (list) => {
      const files = [...list];
      const good = files.filter((f) => this.accept.includes(extensionOf(f.name)));
      for (const f of files) {
        if (!good.includes(f)) onRefuse(`${String(f.name).slice(0, 60)}: not a ${what}; must end in ${this.accept.join(', ')}`);
      }
      if (good.length) onFiles(good);
    };
    let depth = 0;
    target.addEventListener('dragenter', (e) => {
      e.preventDefault();
      ++depth;
      target.classList.add('dropping');
    });
    target.addEventListener('dragover', (e) => e.preventDefault());
    target.addEventListener('dragleave', () => {
      if (--depth <= 0) {
        depth = 0;
        target.classList.remove('dropping');
      }
    });
    target.addEventListener('drop', (e) => {
      e.preventDefault();
      depth = 0;
      target.classList.remove('dropping');
      if (e.dataTransfer?.files?.length) take(e.dataTransfer.files);
    });
    if (input) {
      input.setAttribute('accept', this.accept.join(','));
      input.addEventListener('change', () => {
        if (input.files?.length) take(input.files);
        input.value = '';
      });
    }
  }
}
