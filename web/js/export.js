// export.js — getting the current clip out of the page: BVH and glTF binary (.glb) written by the
// core, and a WebM video of the canvas recorded with MediaRecorder over one play-through.

export function download(bytesOrText, filename, mime) {
  const blob = bytesOrText instanceof Blob ? bytesOrText : new Blob([bytesOrText], { type: mime });
  const url = URL.createObjectURL(blob);
  const a = document.createElement('a');
  a.href = url;
  a.download = filename;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}

export function safeFileStem(label) {
  const stem = (label || 'signweave').normalize('NFKD').replace(/[^\w.-]+/g, '_').replace(/^_+|_+$/g, '');
  return stem.slice(0, 60) || 'signweave';
}

export function webmSupported() {
  return typeof MediaRecorder !== 'undefined' && typeof HTMLCanvasElement.prototype.captureStream === 'function';
}

// Record the canvas while `playThrough` plays the clip once from the start; resolves to a WebM Blob.
export async function recordWebm(canvas, playThrough, { fps = 30 } = {}) {
  if (!webmSupported()) throw new Error('This browser cannot record the canvas (no MediaRecorder).');
  const mime = ['video/webm;codecs=vp9', 'video/webm;codecs=vp8', 'video/webm'].find((m) => MediaRecorder.isTypeSupported(m));
  if (!mime) throw new Error('This browser cannot encode WebM video.');
  const stream = canvas.captureStream(fps);
  const recorder = new MediaRecorder(stream, { mimeType: mime, videoBitsPerSecond: 4_000_000 });
  const chunks = [];
  recorder.ondataavailable = (e) => { if (e.data.size) chunks.push(e.data); };
  const stopped = new Promise((resolve) => { recorder.onstop = resolve; });
  recorder.start(250);
  try {
    await playThrough();
  } finally {
    recorder.stop();
    for (const track of stream.getTracks()) track.stop();
  }
  await stopped;
  return new Blob(chunks, { type: 'video/webm' });
}
