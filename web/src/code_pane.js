// The program's text, one row per line, drawn only where visible so a million lines scroll as
// smoothly as ten. Clicking a line calls onLine(file, line).
const ROW_PX = 18;

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

  const lines = sources.map((text) => text.split(/\r?\n/));
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
      body.textContent = text[n];
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
