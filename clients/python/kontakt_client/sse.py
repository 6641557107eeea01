"""Server-Sent Events parsing (WHATWG HTML): lines in, (id, event, data) frames out."""


def parse_sse(lines):
    """Yields (id, event, data) for each frame of an iterable of text lines.

    `id` is an int when the frame has one (kontaktd always sends it), `data` the joined data
    lines; comment lines (keep-alives) are skipped."""
    frame_id, event, data = None, "message", []
    for raw in lines:
        line = raw.rstrip("\r\n")
        if not line:
            if data:
                yield frame_id, event, "\n".join(data)
            event, data = "message", []
            continue
        if line.startswith(":"):
            continue
        field, _, value = line.partition(":")
        value = value[1:] if value.startswith(" ") else value
        if field == "id":
            frame_id = int(value) if value.isdigit() else value
        elif field == "event":
            event = value
        elif field == "data":
            data.append(value)
