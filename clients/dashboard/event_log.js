// The live tail of a job's event log: the newest `limit` lines, appended in batches; it keeps
// following the end unless the reader scrolled up.
import { el } from "./dom.js";
import { event_text } from "./event_text.js";

export class EventLog {
  constructor(list, limit = 500) {
    this.list = list;
    this.limit = limit;
    this.pending = [];
  }

  /** Queues events; only the newest `limit` can ever be shown, so older ones are dropped now. */
  add(events) {
    this.pending.push(...events);
    if (this.pending.length > this.limit) this.pending.splice(0, this.pending.length - this.limit);
  }

  flush() {
    if (!this.pending.length) return;
    const box = this.list.parentElement;
    const at_end = box.scrollTop + box.clientHeight >= box.scrollHeight - 4;
    const lines = document.createDocumentFragment();
    for (const e of this.pending) lines.append(el("li", { class: `ev-${e.event}` }, event_text(e)));
    this.pending = [];
    this.list.append(lines);
    for (let n = this.list.childElementCount - this.limit; n > 0; n -= 1) this.list.firstElementChild.remove();
    if (at_end) box.scrollTop = box.scrollHeight;
  }
}
