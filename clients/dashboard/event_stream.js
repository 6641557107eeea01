// A job's event stream over fetch(): the token goes in the Authorization header, and after a
// dropped connection the stream resumes with Last-Event-ID, so no event is lost or repeated.
import { api_fetch } from "./api.js";
import { parse_sse } from "./sse_parser.js";

const RETRY_MS = [500, 1000, 2000, 5000, 10000];
const SLICE = 1000;  // events handed to the page at a time

export class EventStream {
  /**
   * @param url        /v1/jobs/ID/events
   * @param on_events  called with each batch of parsed events ({seq, event, ...}), in order
   * @param on_state   called with "live", "reconnecting", "ended" or "failed: ..."
   * @param is_last    an event after which the server closes the stream for good
   */
  constructor(url, { on_events, on_state, is_last }) {
    this.url = url;
    this.on_events = on_events;
    this.on_state = on_state;
    this.is_last = is_last;
    this.last_id = null;
    this.ended = false;
    this.abort = new AbortController();
  }

  async run() {
    let failures = 0;
    while (!this.ended && !this.abort.signal.aborted) {
      try {
        if (await this.read_once()) failures = 0;
      } catch (e) {
        if (this.abort.signal.aborted) return;
        if (e.permanent) {
          this.on_state("failed: " + e.message);
          return;
        }
      }
      if (this.ended) break;
      this.on_state("reconnecting");
      await new Promise((r) => setTimeout(r, RETRY_MS[Math.min(failures, RETRY_MS.length - 1)]));
      failures += 1;
    }
    if (this.ended) this.on_state("ended");
  }

  close() {
    this.abort.abort();
  }

  /** One connection: true when it delivered at least one event. */
  async read_once() {
    const headers = { Accept: "text/event-stream" };
    if (this.last_id !== null) headers["Last-Event-ID"] = this.last_id;
    const response = await api_fetch(this.url, { headers, signal: this.abort.signal });
    if (!response.ok) {
      const error = new Error(`${this.url}: HTTP ${response.status}`);
      error.permanent = response.status === 404 || response.status === 400;
      throw error;
    }
    this.on_state("live");
    const reader = response.body.pipeThrough(new TextDecoderStream()).getReader();
    let buffer = "", delivered = false;
    for (;;) {
      const { value, done } = await reader.read();
      if (done) break;
      const { frames, rest } = parse_sse(buffer + value);
      buffer = rest;
      // A replay arrives in chunks of thousands of events. Hand them over in slices and let
      // timers (the page's redraws) run in between, so a long history draws as it arrives;
      // back-to-back reads alone would resolve as microtasks and starve the timers.
      for (let start = 0; start < frames.length; start += SLICE) {
        const events = frames.slice(start, start + SLICE).map((f) => {
          this.last_id = f.id ?? this.last_id;
          const event = JSON.parse(f.data);
          if (this.is_last(event)) this.ended = true;
          return event;
        });
        delivered = true;
        this.on_events(events);
        await new Promise((resolve) => setTimeout(resolve, 0));
      }
    }
    return delivered;
  }
}
