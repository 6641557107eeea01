// Server-Sent Events framing (WHATWG HTML, "server-sent events"), for streams read with
// fetch(): EventSource cannot send an Authorization header. Pure; tested under node.

/**
 * Splits `text` (what arrived so far) into complete frames and the unfinished rest.
 * Frames: {id, event, data} with data lines joined by "\n"; comment lines are skipped, and a
 * frame without data (a keep-alive) yields nothing.
 */
export function parse_sse(text) {
  const frames = [];
  let start = 0;
  for (;;) {
    const end = frame_end(text, start);
    if (end < 0) break;
    const frame = parse_frame(text.slice(start, end.at));
    if (frame) frames.push(frame);
    start = end.next;
  }
  return { frames, rest: text.slice(start) };
}

/** The first blank line after `from`: {at: where the frame ends, next: after the blank line}. */
function frame_end(text, from) {
  const m = /\r\n\r\n|\n\n|\r\r/g;
  m.lastIndex = from;
  const hit = m.exec(text);
  return hit ? { at: hit.index, next: hit.index + hit[0].length } : -1;
}

function parse_frame(block) {
  let id = null, event = "message";
  const data = [];
  for (const line of block.split(/\r\n|\n|\r/)) {
    if (line === "" || line.startsWith(":")) continue;
    const colon = line.indexOf(":");
    const field = colon < 0 ? line : line.slice(0, colon);
    let value = colon < 0 ? "" : line.slice(colon + 1);
    if (value.startsWith(" ")) value = value.slice(1);
    if (field === "id") id = value;
    else if (field === "event") event = value;
    else if (field === "data") data.push(value);
  }
  return data.length ? { id, event, data: data.join("\n") } : null;
}
