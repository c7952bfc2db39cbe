// The page's data is unpacked on a worker thread while the browser still reads it: the page
// carries its base64 in pieces, each followed by a call to self.nckitData(), which hands the
// pieces read so far to the worker; the worker decodes each piece and feeds it to the browser's
// gzip inflater at once. Once the document is parsed, finish() waits for the inflated bytes.
// Where no worker can be started, the pieces are joined and unpacked on the page's thread.

// The worker's whole program: it runs from its own source text, so it uses nothing from
// around it. Messages in: a string (a piece of base64) or null (the end). Out: { buffer,
// base64Ms, totalMs } with the inflated bytes, or { error }.
function workerMain() {
  const t0 = performance.now();
  const stream = new DecompressionStream("gzip");
  const writer = stream.writable.getWriter();
  const chunks = [];
  let total = 0;
  let base64Ms = 0;
  const read = (async () => {
    const reader = stream.readable.getReader();
    for (;;) {
      const { done, value } = await reader.read();
      if (done) return;
      chunks.push(value);
      total += value.length;
    }
  })();
  read.catch(() => {});
  function decode(text) {
    if (typeof Uint8Array.fromBase64 === "function") return Uint8Array.fromBase64(text);
    const binary = atob(text);
    const bytes = new Uint8Array(binary.length);
    for (let i = 0; i < binary.length; i++) bytes[i] = binary.charCodeAt(i);
    return bytes;
  }
  self.onmessage = async (event) => {
    try {
      if (typeof event.data === "string") {
        const t = performance.now();
        const bytes = decode(event.data.trim());
        base64Ms += performance.now() - t;
        writer.write(bytes).catch(() => {});
        return;
      }
      writer.close().catch(() => {});
      await read;
      const out = new Uint8Array(total);
      let at = 0;
      for (const c of chunks) {
        out.set(c, at);
        at += c.length;
      }
      self.postMessage({ buffer: out.buffer, base64Ms, totalMs: performance.now() - t0 }, [out.buffer]);
    } catch (error) {
      self.postMessage({ error: String(error) });
    }
  };
}

function pieces() {
  const box = document.getElementById("nckit-data");
  return box ? Array.from(box.querySelectorAll("script[type='application/octet-stream']")) : [];
}

//! Starts the worker (if the browser allows one). take(): hands over the pieces read so far;
//! finish(unpackHere): once the document is parsed, the inflated bytes as
//! { buffer, timings }, by the worker or else by unpackHere(the joined base64).
export function startPayload() {
  let worker = null;
  try {
    const source = "(" + workerMain.toString() + ")()";
    worker = new Worker(URL.createObjectURL(new Blob([source], { type: "text/javascript" })));
  } catch (error) {
    console.warn("nckit report: no worker thread, the data is unpacked on the page's thread:", error);
  }
  let sent = 0;
  function take() {
    if (!worker) return;
    const list = pieces();
    for (; sent < list.length; sent++) worker.postMessage(list[sent].textContent);
  }
  async function finish(unpackHere) {
    if (!worker) return unpackHere(pieces().map((p) => p.textContent.trim()).join(""));
    take();
    const t0 = performance.now();
    const reply = await new Promise((resolve) => {
      worker.onmessage = (event) => resolve(event.data);
      worker.onerror = (event) => resolve({ error: event.message || "worker failed" });
      worker.postMessage(null);
    });
    worker.terminate();
    if (reply.error) throw new Error("nckit report: the page's data could not be unpacked: " + reply.error);
    const timings = { worker_base64: Math.round(reply.base64Ms), worker_total: Math.round(reply.totalMs), wait: Math.round(performance.now() - t0) };
    return { buffer: reply.buffer, timings };
  }
  return { take, finish };
}
