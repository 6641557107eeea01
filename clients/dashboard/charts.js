// uPlot charts of the dashboard: a factory with the options every chart shares (width follows
// its box, log or linear y, synced cursors, vertical markers), and the points counter the
// browser tests and the render benchmark read.
import { fmt_legend, fmt_log_tick, fmt_tick, is_decade } from "./axis_format.js";
import uPlot from "./uPlot.esm.js";

const HEIGHT = 260;

// Boundary and event markers: [colour, width in CSS px, dash].
const MARKER_STYLE = {
  increment: ["rgba(0, 0, 0, 0.3)", 1, []],
  step: ["rgba(0, 0, 0, 0.55)", 1, []],
  run: ["#1769aa", 2, []],
  cutback: ["#c62828", 1.5, [4, 3]],
  drift: ["#e67e00", 1.5, [4, 3]],
};

export const COLORS = ["#1769aa", "#2e7d32", "#8e24aa", "#00838f", "#c0392b", "#6d4c41"];

/** Vertical lines at the markers in view; increment boundaries only while they stay apart. */
function draw_markers(u, markers) {
  const { left, top, width, height } = u.bbox;
  const { min, max } = u.scales.x;
  const visible = markers.filter((m) => m.x >= min && m.x <= max);
  const boundaries = visible.reduce((n, m) => n + (m.kind === "increment"), 0);
  const show_boundaries = boundaries * 4 * u.pxRatio < width;
  const ctx = u.ctx;
  ctx.save();
  ctx.beginPath();
  ctx.rect(left, top, width, height);
  ctx.clip();
  for (const m of visible) {
    if (m.kind === "increment" && !show_boundaries) continue;
    const [color, w, dash] = MARKER_STYLE[m.kind];
    const px = Math.round(u.valToPos(m.x, "x", true)) + 0.5;
    ctx.strokeStyle = color;
    ctx.lineWidth = w * u.pxRatio;
    ctx.setLineDash(dash.map((d) => d * u.pxRatio));
    ctx.beginPath();
    ctx.moveTo(px, top);
    ctx.lineTo(px, top + height);
    ctx.stroke();
  }
  ctx.restore();
}

/**
 * A line chart in `box`.
 * series: [{label, stroke, points_only, point_size, span_gaps, value}], x: {label, value,
 * categories}, y: {label, log},
 * markers: () => [{x, kind}], sync: cursor sync key, on_first_draw: called once data shows.
 */
export function make_chart(box, { x, y, series, markers, sync, on_first_draw }) {
  let drawn = false;
  const hooks = {
    draw: [(u) => {
      if (markers) draw_markers(u, markers());
      if (!drawn && u.data[0].length > 0) {
        drawn = true;
        if (on_first_draw) on_first_draw();
      }
    }],
  };
  const x_scale = { time: false };
  if (x.categories) x_scale.distr = 2;
  const y_axis = { label: y.label, size: 64, values: (u, splits) => splits.map(fmt_tick) };
  if (y.log) {
    // Over more than a decade, labels and grid at the decades only: the 2..9 lines would
    // grey the plot out.
    const decades = (u, splits) => {
      const { min, max } = u.scales.y;
      return max / min < 20 ? splits : splits.map((v) => (is_decade(v) ? v : null));
    };
    Object.assign(y_axis, { filter: decades, grid: { filter: decades }, ticks: { filter: decades },
                            values: (u, splits) => splits.map((v) => (v === null ? null : fmt_log_tick(v))) });
  }
  const opts = {
    width: box.clientWidth || 600,
    height: HEIGHT,
    scales: { x: x_scale, y: y.log ? { distr: 3 } : {} },
    axes: [
      { label: x.label, values: x.categories ? (u, ticks) => ticks.map((i) => x.categories()[i] ?? "") : undefined },
      y_axis,
    ],
    series: [
      { label: x.label, value: x.value },
      ...series.map((s, i) => ({
        label: s.label,
        stroke: s.stroke || COLORS[i % COLORS.length],
        width: s.points_only ? 0 : 1.5,
        paths: s.points_only ? () => null : undefined,
        points: s.points_only ? { show: true, size: 8, fill: s.stroke, stroke: s.stroke } : { size: s.point_size || 4 },
        value: s.value || ((u, v) => (v === null || v === undefined ? "–" : fmt_legend(v))),
        spanGaps: Boolean(s.span_gaps),
      })),
    ],
    cursor: sync ? { sync: { key: sync } } : {},
    hooks,
  };
  const u = new uPlot(opts, [[], ...series.map(() => [])], box);
  new ResizeObserver(() => {
    if (box.clientWidth && box.clientWidth !== u.width) u.setSize({ width: box.clientWidth, height: HEIGHT });
  }).observe(box);
  return u;
}

/** Hands `data` to the chart and records on its box how many points it holds. */
export function show_data(u, data, box, n_points) {
  u.setData(data);
  box.dataset.points = String(n_points);
}

