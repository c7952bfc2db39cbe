// Charts with uPlot: each axis's velocity, acceleration and jerk against time with the machine's
// limits drawn as dashed lines, and generic x–y charts for the process pages.
import uPlot from "uplot";
import { axisColors } from "./colors.js";
import { scalePlot } from "./scale_plot.js";

function chartBox(parent, title) {
  const box = document.createElement("div");
  box.className = "chart";
  const h = document.createElement("h3");
  h.textContent = title;
  box.appendChild(h);
  parent.appendChild(box);
  return box;
}

function width(parent) {
  return Math.max(320, Math.min(parent.clientWidth - 20, 900));
}

//! One chart per quantity, series per axis, ±limit lines in the axis colour, dashed.
export function axisCharts(parent, samples, axes, machineAxes, onTime) {
  const quantities = [
    ["velocity", "vel", "max_velocity", "/s"],
    ["acceleration", "acc", "max_acceleration", "/s²"],
    ["jerk", "jerk", "max_jerk", "/s³"],
  ];
  const plots = [];
  for (const [name, key, limitKey, unit] of quantities) {
    const box = chartBox(parent, `${name} of each axis against time (dashed: machine limits)`);
    const data = [samples.t];
    const series = [{ label: "t (s)" }];
    axes.forEach((a, i) => {
      const rotary = machineAxes[i].rotary;
      data.push(samples[key][a]);
      series.push({ label: `${a} (${rotary ? "deg" : "mm"}${unit})`, stroke: axisColors[i % axisColors.length], width: 1 });
    });
    axes.forEach((a, i) => {
      const limit = machineAxes[i][limitKey];
      if (!isFinite(limit) || limit <= 0) return;
      for (const sign of [1, -1]) {
        data.push(new Float64Array(samples.t.length).fill(sign * limit));
        series.push({ label: `${sign > 0 ? "+" : "−"}${a} limit`, stroke: axisColors[i % axisColors.length], dash: [6, 4], width: 1, points: { show: false } });
      }
    });
    const plot = new uPlot(
      {
        width: width(parent),
        height: 220,
        series,
        scales: { x: { time: false } },
        axes: [{ label: "t (s)" }, { label: name }],
        legend: { live: true },
        cursor: { drag: { x: true, y: false } },
        hooks: { setCursor: [(u) => u.cursor.idx != null && onTime && onTime(u.cursor.idx, false)] },
      },
      data,
      box,
    );
    plots.push(plot);
  }
  return plots;
}

export function speedChart(parent, samples) {
  const box = chartBox(parent, "tool speed along X Y Z against time (mm/min)");
  const speed = Float64Array.from(samples.speed, (v) => v * 60);
  return new uPlot(
    {
      width: width(parent),
      height: 180,
      series: [{ label: "t (s)" }, { label: "speed (mm/min)", stroke: "#333", width: 1 }],
      scales: { x: { time: false } },
      axes: [{ label: "t (s)" }, { label: "mm/min" }],
    },
    [samples.t, speed],
    box,
  );
}

//! A process chart: series may have their own x values (merged onto one x axis by uPlot's
//! "mode 2" data, each series with its own x array).
export function xyChart(parent, chart, blob) {
  const box = chartBox(parent, chart.title);
  if (chart.equal_axes) return scalePlot(box, chart, blob, width(parent));
  const data = [null];
  const series = [{}];
  let xmin = Infinity, xmax = -Infinity, ymin = Infinity, ymax = -Infinity;
  chart.series.forEach((s, i) => {
    const x = blob(s.x);
    const y = blob(s.y);
    for (let k = 0; k < x.length; k++) {
      if (Number.isNaN(x[k]) || Number.isNaN(y[k])) continue;
      if (x[k] < xmin) xmin = x[k];
      if (x[k] > xmax) xmax = x[k];
      if (y[k] < ymin) ymin = y[k];
      if (y[k] > ymax) ymax = y[k];
    }
    // NaN separates the pieces of one series (a gap in the line).
    const gap = (v) => (Number.isNaN(v) ? null : v);
    data.push([Array.from(x, gap), Array.from(y, gap)]);
    series.push({ label: s.name, stroke: axisColors[i % axisColors.length], width: 1.5, points: { show: x.length < 60 } });
  });
  for (const line of chart.y_lines) {
    data.push([Float64Array.of(xmin, xmax), Float64Array.of(line.value, line.value)]);
    series.push({ label: line.label, stroke: "#888", dash: [6, 4], width: 1, points: { show: false } });
    ymin = Math.min(ymin, line.value);
    ymax = Math.max(ymax, line.value);
  }
  const w = width(parent);
  let h = 260;
  const scales = { x: { time: false }, y: chart.log_y ? { distr: 3 } : {} };
  if (chart.equal_axes && isFinite(xmin)) {
    // To scale: the same length per pixel on both axes, the plot area sized to fit.
    const pad = 0.05 * Math.max(xmax - xmin, ymax - ymin);
    const sx = xmax - xmin + 2 * pad;
    const sy = ymax - ymin + 2 * pad;
    h = Math.min(600, Math.max(160, Math.round(((w - 80) * sy) / sx) + 60));
    const plotH = h - 60;
    const plotW = w - 80;
    const unit = Math.max(sx / plotW, sy / plotH);
    const cx = (xmin + xmax) / 2;
    const cy = (ymin + ymax) / 2;
    scales.x = { time: false, range: [cx - (unit * plotW) / 2, cx + (unit * plotW) / 2] };
    scales.y = { range: [cy - (unit * plotH) / 2, cy + (unit * plotH) / 2] };
  }
  return new uPlot(
    {
      mode: 2,
      width: w,
      height: h,
      series,
      scales,
      axes: [{ label: chart.x_label }, { label: chart.y_label }],
    },
    data,
    box,
  );
}
