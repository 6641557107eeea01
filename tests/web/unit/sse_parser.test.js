// SSE framing as the job page reads it over fetch(): frames split anywhere across chunks.
import assert from "node:assert/strict";
import { test } from "node:test";
import { parse_sse } from "../../../clients/dashboard/sse_parser.js";

const STREAM = "id: 1\nevent: status\ndata: {\"seq\":1}\n\n: keep-alive\n\n" +
               "id: 2\nevent: iteration\ndata: {\"seq\":2,\"residual\":0.5}\n\n";

test("whole frames parse, comments and keep-alives yield nothing", () => {
  const { frames, rest } = parse_sse(STREAM);
  assert.deepEqual(frames, [
    { id: "1", event: "status", data: "{\"seq\":1}" },
    { id: "2", event: "iteration", data: "{\"seq\":2,\"residual\":0.5}" },
  ]);
  assert.equal(rest, "");
});

test("a stream cut at every position gives the same frames", () => {
  const whole = parse_sse(STREAM).frames;
  for (let cut = 0; cut <= STREAM.length; cut += 1) {
    const first = parse_sse(STREAM.slice(0, cut));
    const second = parse_sse(first.rest + STREAM.slice(cut));
    assert.deepEqual([...first.frames, ...second.frames], whole, `cut at ${cut}`);
  }
});

test("CRLF and CR line ends, multi-line data, no space after the colon", () => {
  const { frames } = parse_sse("id:7\r\nevent:x\r\ndata:a\r\ndata: b\r\n\r\nid: 8\rdata: c\r\r");
  assert.deepEqual(frames, [{ id: "7", event: "x", data: "a\nb" }, { id: "8", event: "message", data: "c" }]);
});

test("an unfinished frame stays in the rest", () => {
  const { frames, rest } = parse_sse("id: 3\ndata: {\"seq\":3}\n");
  assert.deepEqual(frames, []);
  assert.equal(rest, "id: 3\ndata: {\"seq\":3}\n");
});
