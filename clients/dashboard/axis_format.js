// Axis choices, tick labels and legend values of the plots (pure; tested under node).

export function is_decade(v) {
  const e = Math.log10(v);
  return Math.abs(e - Math.round(e)) < 1e-9;
}

/** 1e-7, 0.01, 0.1, 1, 10, 100, 1e4; 0.3, 2e-5 between decades */
export function fmt_log_tick(v) {
  const e = Math.floor(Math.log10(v) + 1e-9);
  if (e >= -2 && e <= 3) return String(Number(v.toPrecision(2)));
  const m = Number((v / 10 ** e).toPrecision(2));
  return m === 1 ? `1e${e}` : `${m}e${e}`;
}

/** Linear-axis ticks: 3 significant digits, exponent form for small or large magnitudes. */
export function fmt_tick(v) {
  if (v === null) return null;
  const a = Math.abs(v);
  return a !== 0 && (a >= 1e5 || a < 1e-2) ? v.toExponential(1).replace("e+", "e") : String(Number(v.toPrecision(3)));
}

/** A log axis suits a positive measure that spans two decades or more. */
export function prefers_log(column) {
  let min = Infinity, max = 0;
  for (const v of column) {
    if (v === null) continue;
    if (v <= 0) return false;
    min = Math.min(min, v);
    max = Math.max(max, v);
  }
  return max > 0 && max / min >= 100;
}

/** A value in a plot's legend: 4 significant digits, exponent form outside [1e-3, 1e5). */
export function fmt_legend(v) {
  const a = Math.abs(v);
  return a !== 0 && (a >= 1e5 || a < 1e-3) ? v.toExponential(3) : String(Number(v.toPrecision(4)));
}
