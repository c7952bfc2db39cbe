// Unpacks the page's data: base64 → gzip (the browser's own DecompressionStream) → a JSON header
// and typed arrays (payload_worker.js does the first two steps on a worker thread) (layout in docs/report.md, written by src/report/payload.cpp).

function decodeDelta(bytes, count, scale) {
  const out = new Float64Array(count);
  let pos = 0;
  let acc = 0;
  for (let i = 0; i < count; i++) {
    let b = bytes[pos++];
    if (b < 0x80) {
      // One byte, the common case: zigzag in integer arithmetic.
      acc += (b >>> 1) ^ -(b & 1);
    } else {
      let value = b & 0x7f;
      let factor = 128;
      do {
        b = bytes[pos++];
        value += (b & 0x7f) * factor;
        factor *= 128;
      } while (b & 0x80);
      // zigzag: even numbers are the non-negative deltas, odd ones the negative
      acc += value % 2 === 1 ? -(value + 1) / 2 : value / 2;
    }
    out[i] = acc * scale;
  }
  return out;
}

//! gzip → bytes with the browser's DecompressionStream, the whole input written at once (a
//! Blob's stream would hand it over in small pieces, each a task of its own).
async function gunzip(packed) {
  const stream = new DecompressionStream("gzip");
  const writer = stream.writable.getWriter();
  writer.write(packed).catch(() => {});
  writer.close().catch(() => {});
  const reader = stream.readable.getReader();
  const chunks = [];
  let total = 0;
  for (;;) {
    const { done, value } = await reader.read();
    if (done) break;
    chunks.push(value);
    total += value.length;
  }
  const out = new Uint8Array(total);
  let at = 0;
  for (const c of chunks) {
    out.set(c, at);
    at += c.length;
  }
  return out.buffer;
}

//! base64 text → the inflated bytes, on the page's own thread (where no worker can run).
export async function unpackHere(base64Text) {
  // Uint8Array.fromBase64 where the browser has it (Chromium 140 on), else atob; both far
  // faster than fetching a data: URL of the same text.
  const t0 = performance.now();
  const text = base64Text.trim();
  let packed;
  if (typeof Uint8Array.fromBase64 === "function") {
    packed = Uint8Array.fromBase64(text);
  } else {
    const binary = atob(text);
    packed = new Uint8Array(binary.length);
    for (let i = 0; i < binary.length; i++) packed[i] = binary.charCodeAt(i);
  }
  const t1 = performance.now();
  const buffer = await gunzip(packed);
  const t2 = performance.now();
  return { buffer, timings: { base64: Math.round(t1 - t0), gunzip: Math.round(t2 - t1) } };
}

//! The inflated bytes → the header and a blob(name) reader of the typed arrays.
export function readPayload({ buffer, timings }) {
  const headerLength = new DataView(buffer).getUint32(0, true);
  const header = JSON.parse(new TextDecoder().decode(new Uint8Array(buffer, 4, headerLength)));
  const base = Math.ceil((4 + headerLength) / 8) * 8;
  const cache = new Map();
  function blob(name) {
    if (cache.has(name)) return cache.get(name);
    const e = header.blobs && header.blobs[name];
    if (!e) throw new Error("page data has no " + name);
    const at = base + e.offset;
    let value;
    if (e.type === "u8") value = new Uint8Array(buffer, at, e.length);
    else if (e.type === "f32") value = new Float32Array(buffer.slice(at, at + e.length));
    else if (e.type === "f64") value = new Float64Array(buffer.slice(at, at + e.length));
    else if (e.type === "text") value = new TextDecoder().decode(new Uint8Array(buffer, at, e.length));
    else if (e.type === "delta") value = decodeDelta(new Uint8Array(buffer, at, e.length), e.count, e.scale);
    else throw new Error("unknown blob type " + e.type);
    cache.set(name, value);
    return value;
  }
  //! A text blob as its UTF-8 bytes (no string made of it).
  blob.bytes = (name) => {
    const e = header.blobs && header.blobs[name];
    if (!e || e.type !== "text") throw new Error("page data has no text " + name);
    return new Uint8Array(buffer, base + e.offset, e.length);
  };
  return { header, blob, bytes: buffer.byteLength, timings };
}
