// The job list's state (status and label filters, page size, page tokens) as it lives in the
// page's URL, so a filtered page can be linked, reloaded and navigated with back/forward;
// and the API request it makes. Pure; tested under node.

export const STATUSES = ["queued", "running", "canceling", "succeeded", "failed", "canceled"];
export const PAGE_SIZES = [50, 100, 200];

/**
 * ?status=queued,running&label=k=v&limit=100&page_token=T&back=,T1 -> the state.
 * `back` lists the tokens of the pages before this one ("" = the first page).
 */
export function read_state(search) {
  const q = new URLSearchParams(search);
  const statuses = q.getAll("status").flatMap((s) => s.split(",")).filter((s) => STATUSES.includes(s));
  const limit = Number(q.get("limit"));
  return {
    statuses,
    labels: q.getAll("label").filter((l) => l.includes("=")),
    limit: PAGE_SIZES.includes(limit) ? limit : PAGE_SIZES[0],
    page_token: q.get("page_token") || null,
    back: q.has("back") ? q.get("back").split(",") : [],
  };
}

/** The state as the page's query string ("" for the unfiltered first page). */
export function state_query(s) {
  const q = new URLSearchParams();
  if (s.statuses.length) q.set("status", s.statuses.join(","));
  for (const l of s.labels) q.append("label", l);
  if (s.limit !== PAGE_SIZES[0]) q.set("limit", String(s.limit));
  if (s.page_token) {
    q.set("page_token", s.page_token);
    q.set("back", s.back.join(","));
  }
  const text = q.toString();
  return text ? "?" + text : "";
}

/** GET /v1/jobs for the state. */
export function api_url(s) {
  const q = new URLSearchParams();
  if (s.statuses.length) q.set("status", s.statuses.join(","));
  for (const l of s.labels) q.append("label", l);
  q.set("limit", String(s.limit));
  if (s.page_token) q.set("page_token", s.page_token);
  return "/v1/jobs?" + q.toString();
}

/** The state of the next page (after a page whose next_page_token is `token`). */
export function next_page(s, token) {
  return { ...s, page_token: token, back: [...s.back, s.page_token || ""] };
}

/** The state of the previous page; the first page's when there is none. */
export function previous_page(s) {
  const back = s.back.slice(0, -1);
  return { ...s, page_token: s.back.at(-1) || null, back };
}

/** The first page of a new filter. */
export function first_page(statuses, labels, limit) {
  return { statuses, labels, limit, page_token: null, back: [] };
}

/**
 * "load=12, case=a" -> {labels: ["load=12", "case=a"]}, or {error} naming the bad entry.
 * Keys as the API takes them: 1 to 64 of A-Z a-z 0-9 _ - .
 */
export function parse_label_filter(text) {
  const labels = [];
  for (const part of text.split(",").map((p) => p.trim()).filter(Boolean)) {
    const eq = part.indexOf("=");
    const key = (eq < 0 ? part : part.slice(0, eq)).trim();
    if (eq < 0 || !/^[A-Za-z0-9_.-]{1,64}$/.test(key))
      return { error: `"${part}": expected key=value (key: letters, digits, _ - .)` };
    labels.push(key + "=" + part.slice(eq + 1).trim());
  }
  return { labels };
}
