// Number, size, time and duration formatting for the dashboard (pure; tested under node).

/** A measure with 3 significant digits: exponent form outside [1e-3, 1e5), "" for null. */
export function fmt_number(v) {
  if (v === null || v === undefined || Number.isNaN(v)) return "";
  if (v === 0) return "0";
  const a = Math.abs(v);
  if (a >= 1e5 || a < 1e-3) return v.toExponential(2);
  return String(Number(v.toPrecision(3)));
}

/** Bytes as B, KiB, MiB, GiB with 3 significant digits. */
export function fmt_bytes(n) {
  if (n === null || n === undefined) return "";
  const units = ["B", "KiB", "MiB", "GiB", "TiB"];
  let i = 0;
  let v = n;
  while (v >= 1024 && i < units.length - 1) {
    v /= 1024;
    i += 1;
  }
  return i === 0 ? `${n} B` : `${Number(v.toPrecision(3))} ${units[i]}`;
}

/** Seconds as "0.42 s", "12.3 s", "4 min 05 s", "2 h 03 min". */
export function fmt_duration(seconds) {
  if (seconds === null || seconds === undefined || Number.isNaN(seconds)) return "";
  if (seconds < 0) seconds = 0;
  if (seconds < 60) return `${Number(seconds.toPrecision(seconds < 1 ? 2 : 3))} s`;
  const s = Math.round(seconds);
  const h = Math.floor(s / 3600), m = Math.floor((s % 3600) / 60), r = s % 60;
  const two = (x) => String(x).padStart(2, "0");
  return h > 0 ? `${h} h ${two(m)} min` : `${m} min ${two(r)} s`;
}

/** RFC 3339 UTC ("2026-11-22T10:00:00.123Z") as local "2026-11-22 11:00:00"; "" for null. */
export function fmt_time(rfc3339) {
  if (!rfc3339) return "";
  const d = new Date(rfc3339);
  if (Number.isNaN(d.getTime())) return rfc3339;
  const two = (x) => String(x).padStart(2, "0");
  return `${d.getFullYear()}-${two(d.getMonth() + 1)}-${two(d.getDate())} ` +
         `${two(d.getHours())}:${two(d.getMinutes())}:${two(d.getSeconds())}`;
}

/** Seconds between two RFC 3339 times (or until `now_ms` when `to` is null); null if unknown. */
export function seconds_between(from, to, now_ms) {
  if (!from) return null;
  const end = to ? Date.parse(to) : now_ms;
  return (end - Date.parse(from)) / 1000;
}
