// Small DOM builders shared by the pages. Text always goes in as textContent, never as HTML:
// job names, labels and solver messages come from users.

/** el("td", {class: "num", title: "...", style: {width: "5%"}}, "text", child, ...) */
export function el(tag, attrs = {}, ...children) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (v === null || v === undefined || v === false) continue;
    if (k === "class") node.className = v;
    else if (k === "style") Object.assign(node.style, v);  // CSSOM: allowed by the page's CSP
    else if (k.startsWith("on")) node.addEventListener(k.slice(2), v);
    else node.setAttribute(k, v === true ? "" : v);
  }
  for (const c of children) {
    if (c === null || c === undefined) continue;
    node.append(c instanceof Node ? c : String(c));
  }
  return node;
}

/** The status chip: "failed: not_converged" unless the reason only repeats the status. */
export function status_chip(status, reason) {
  const code = reason && typeof reason === "object" ? reason.code : reason;
  const text = code && code !== status ? `${status}: ${code}` : status;
  return el("span", { class: `chip ${status}`, "data-status": status }, text);
}

/** Label chips: the key opens the sweep over it, the value filters the job list. */
export function label_chips(labels) {
  const span = el("span", { class: "labels" });
  for (const [k, v] of Object.entries(labels || {})) {
    span.append(el("span", { class: "label" },
      el("a", { href: `/sweeps?label=${encodeURIComponent(k)}`, title: `sweep over ${k}` }, k),
      "=",
      el("a", { href: `/?label=${encodeURIComponent(k + "=" + v)}`, title: `jobs with ${k}=${v}` }, v)));
  }
  return span;
}

/** Replaces the children of the element with id `id`. */
export function fill(id, ...children) {
  document.getElementById(id).replaceChildren(...children.filter((c) => c !== null && c !== undefined));
}
