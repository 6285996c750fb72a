// Reused GL buffers for meshes that are replaced often (the tree page's setTree): each named slot
// keeps one buffer and its capacity; a new upload that fits goes in with bufferSubData (no new
// allocation, no orphaned old storage), a bigger one allocates once with bufferData (issue 17:
// gl.bufferData of every array on each new tree froze the page going from a big tree to a smaller
// one). A slot far bigger than its last few uploads is shrunk so a single huge tree does not hold
// its memory forever.
// Does not: set vertex attributes (buffers.js), know any mesh layout, or delete buffers it did not
// create.

// A slot whose capacity is more than SHRINK_FACTOR times its upload and above SHRINK_BYTES is
// reallocated at the upload's size.
export const SHRINK_FACTOR = 8;
export const SHRINK_BYTES = 64 * 1024 * 1024;

export class BufferPool {
  constructor(gl) {
    this.gl = gl;
    this.slots = new Map();  // name -> {buffer, capacity}
    this.stats = { allocations: 0, subUploads: 0, bytes: 0 };
  }

  // The buffer of slot `name` holding `bytes` (an ArrayBuffer or view) at offset 0, left bound to
  // `target`. The buffer's storage may be larger than `bytes`: draws must use counts, not its size.
  upload(name, bytes, target = this.gl.ARRAY_BUFFER) {
    const gl = this.gl;
    const size = bytes.byteLength;
    let slot = this.slots.get(name);
    if (!slot) {
      slot = { buffer: gl.createBuffer(), capacity: -1 };
      this.slots.set(name, slot);
    }
    gl.bindBuffer(target, slot.buffer);
    const tooBig = slot.capacity > SHRINK_BYTES && slot.capacity > SHRINK_FACTOR * size;
    if (size > slot.capacity || tooBig) {
      gl.bufferData(target, bytes, gl.DYNAMIC_DRAW);
      slot.capacity = size;
      this.stats.allocations += 1;
    } else if (size > 0) {
      gl.bufferSubData(target, 0, bytes);
      this.stats.subUploads += 1;
    }
    this.stats.bytes += size;
    return slot.buffer;
  }

  // True when `buffer` belongs to this pool (callers must not delete it).
  owns(buffer) {
    for (const slot of this.slots.values()) if (slot.buffer === buffer) return true;
    return false;
  }

  // Deletes every slot's buffer.
  dispose() {
    for (const slot of this.slots.values()) this.gl.deleteBuffer(slot.buffer);
    this.slots.clear();
  }
}
