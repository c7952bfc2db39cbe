// The program's text, one row per line, drawn only where visible so a million lines scroll as
// smoothly as ten. Each source stays the UTF-8 bytes the page carries: only the offsets of its
// line starts are found up front (one pass over the bytes), and a line becomes a string when it
// is drawn, so a 28 MB program costs no million strings at load. Clicking a line calls
// onLine(file, line).
const ROW_PX = 18;
const NEWLINE = 10;
const RETURN = 13;

//! Offsets of every line's first byte, and one past the end as the last entry.
function lineStarts(bytes) {
  let count = 1;
  for (let i = 0; i < bytes.length; i++) if (bytes[i] === NEWLINE) count++;
  const starts = new Uint32Array(count + 1);
  let n = 1;
  for (let i = 0; i < bytes.length; i++) if (bytes[i] === NEWLINE) starts[n++] = i + 1;
  starts[count] = bytes.length + 1;
  return starts;
}

function sourceText(bytes) {
  const starts = lineStarts(bytes);
  const decoder = new TextDecoder();
  return {
    length: starts.length - 1,
    line(n) {
      let end = starts[n + 1] - 1; // the newline (or the end of the text)
      if (end > starts[n] && bytes[end - 1] === RETURN) end--;
      return decoder.decode(bytes.subarray(starts[n], end));
    },
  };
}

//! `sources`: one Uint8Array of UTF-8 text per file.
export function createCodePane(container, files, sources, onLine) {
  const tabs = document.createElement("div");
  tabs.className = "code-tabs";
  const scroller = document.createElement("div");
  scroller.className = "code-scroll";
  const spacer = document.createElement("div");
  spacer.className = "code-spacer";
  const rows = document.createElement("div");
  rows.className = "code-rows";
  spacer.appendChild(rows);
  scroller.appendChild(spacer);
  container.append(tabs, scroller);

  const lines = sources.map(sourceText);
  let file = 0;
  let marked = null; // [file, line]

  files.forEach((name, i) => {
    const tab = document.createElement("button");
    tab.textContent = name.split("/").pop();
    tab.title = name;
    tab.addEventListener("click", () => show(i));
    tabs.appendChild(tab);
  });

  function show(i) {
    file = i;
    [...tabs.children].forEach((t, k) => t.classList.toggle("active", k === i));
    spacer.style.height = lines[i].length * ROW_PX + "px";
    draw();
  }

  function draw() {
    const first = Math.max(0, Math.floor(scroller.scrollTop / ROW_PX) - 5);
    const count = Math.ceil((scroller.clientHeight || 600) / ROW_PX) + 10;
    const text = lines[file];
    rows.style.transform = `translateY(${first * ROW_PX}px)`;
    const out = [];
    for (let n = first; n < Math.min(text.length, first + count); n++) {
      const row = document.createElement("div");
      row.className = "code-line";
      row.dataset.line = String(n + 1);
      if (marked && marked[0] === file && marked[1] === n + 1) row.classList.add("selected");
      const number = document.createElement("span");
      number.className = "ln";
      number.textContent = String(n + 1);
      const body = document.createElement("span");
      body.textContent = text.line(n);
      row.append(number, body);
      out.push(row);
    }
    rows.replaceChildren(...out);
  }

  rows.addEventListener("click", (e) => {
    const row = e.target.closest(".code-line");
    if (row) onLine(file, Number(row.dataset.line));
  });
  scroller.addEventListener("scroll", () => requestAnimationFrame(draw));

  function reveal(fileIndex, line) {
    if (fileIndex !== file) show(fileIndex);
    const top = (line - 1) * ROW_PX;
    if (top < scroller.scrollTop || top > scroller.scrollTop + scroller.clientHeight - 2 * ROW_PX) {
      scroller.scrollTop = Math.max(0, top - scroller.clientHeight / 3);
    }
    draw();
  }

  function mark(fileIndex, line) {
    marked = line > 0 ? [fileIndex, line] : null;
    if (marked) reveal(fileIndex, line);
    else draw();
  }

  //! The row element of a line if it is drawn (for tests: a real element to click).
  function rowOf(line) {
    return rows.querySelector(`.code-line[data-line="${line}"]`);
  }

  if (files.length) show(0);
  return { mark, reveal, rowOf, currentFile: () => file, draw };
}
