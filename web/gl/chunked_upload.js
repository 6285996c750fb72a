// Big meshes go up in 4 MB parts (issue 16/17: one bufferData of a 15-year sakura blocked the tree
// page 3.7 s in Chromium on SwiftShader, the ivy page's 125 k-internode mesh 1.7 s): each buffer
// is allocated once, then filled UPLOAD_PART_BYTES at a time with bufferSubData, the next part once
// the GPU has taken the last one (gpuDone), so input and frames run in between. The tree, ivy and terrain
// renderers use it; their old geometry stays drawn until the new one is in place.
// Does not: set vertex attributes or vertex arrays (the renderer binds the finished buffers), know
// any mesh layout, or delete the buffers it returns.

// Plans of more than UPLOAD_PARTS_ABOVE bytes go up in parts of UPLOAD_PART_BYTES.
export const UPLOAD_PARTS_ABOVE = 4 * 1024 * 1024;
export const UPLOAD_PART_BYTES = 4 * 1024 * 1024;  // paced by gpuDone: 66 MB in 1 MB parts took 4.7 s

const wait = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

// Resolves once the GPU has finished everything issued so far (a fence, polled every few ms: the
// main thread stays free). Parts are paced by it: handing the GPU process megabytes faster than it
// takes them fills the command buffer, and the next GL call then blocks the main thread (a 2.5 s
// long task behind a busy SwiftShader).
export async function gpuDone(gl) {
  const fence = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
  if (!fence) return;
  gl.flush();
  while (!gl.isContextLost() && gl.getSyncParameter(fence, gl.SYNC_STATUS) !== gl.SIGNALED) await wait(4);
  if (!gl.isContextLost()) gl.deleteSync(fence);
}

// Bytes of a plan ([{key, bytes, target}], bytes an ArrayBuffer or a view).
export const planBytes = (plan) => plan.reduce((n, p) => n + p.bytes.byteLength, 0);

// Creates one STATIC_DRAW buffer per plan item ({key, bytes, target}) and fills them
// UPLOAD_PART_BYTES at a time (a part may span the end of one buffer and the start of the next),
// yielding to the event loop between parts; resolves to Map(key -> buffer), early with what it has
// once cancelled() is true (the caller deletes them). Each part waits for the GPU to finish the one
// before (gpuDone); the last is not waited for (the caller's draws queue behind it on the GPU).
// Issue 32 item 5: a wait after each buffer (a tree has some 20, most under a part) and after the
// last part cost the default tree's edit 0.5-1 s of fence round trips on a loaded SwiftShader.
// A plan of at most UPLOAD_PARTS_ABOVE bytes is uploaded at once, without yielding.
export async function uploadInParts(gl, plan, cancelled = () => false) {
  const buffers = new Map();
  let left = planBytes(plan);  // bytes not handed to the GPU yet
  let room = UPLOAD_PART_BYTES;  // bytes the part going up may still take
  const parts = left > UPLOAD_PARTS_ABOVE;
  for (const { key, bytes, target } of plan) {
    const u8 = ArrayBuffer.isView(bytes) ? new Uint8Array(bytes.buffer, bytes.byteOffset, bytes.byteLength) : new Uint8Array(bytes);
    const buffer = gl.createBuffer();
    buffers.set(key, buffer);
    gl.bindVertexArray(null);  // an element buffer bound with a vertex array bound would join it
    gl.bindBuffer(target, buffer);
    if (!parts) {
      gl.bufferData(target, u8, gl.STATIC_DRAW);
      continue;
    }
    gl.bufferData(target, u8.byteLength, gl.STATIC_DRAW);
    for (let offset = 0; offset < u8.byteLength;) {
      if (cancelled()) return buffers;
      const end = Math.min(u8.byteLength, offset + room);
      gl.bindVertexArray(null);
      gl.bindBuffer(target, buffer);
      gl.bufferSubData(target, offset, u8.subarray(offset, end));
      left -= end - offset;
      room -= end - offset;
      offset = end;
      if (room === 0 && left > 0) {  // a whole part is up: the next once the GPU has taken it
        await gpuDone(gl);
        room = UPLOAD_PART_BYTES;
      }
    }
  }
  return buffers;
}
