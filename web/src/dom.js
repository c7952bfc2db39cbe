export function el(tag, className, text) {
  const e = document.createElement(tag);
  if (className) e.className = className;
  if (text !== undefined) e.textContent = text;
  return e;
}

//! A two-column table of figures; `html` allows markup in the values (ours, never the program's).
export function figureTable(rows, html) {
  const table = el("table", "figures");
  for (const [name, value] of rows) {
    const tr = el("tr");
    const th = el("th", null, name);
    const td = el("td");
    if (html) td.innerHTML = value;
    else td.textContent = value;
    tr.append(th, td);
    table.appendChild(tr);
  }
  return table;
}
