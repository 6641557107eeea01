"""Python client for kontaktd, standard library only.

    from kontakt_client import Client
    c = Client("http://127.0.0.1:8080")
    job = c.submit_file("model.inp", name="run 1", labels={"sweep": "a"})
    final = job.wait()                 # polls; job.wait(stream=True) follows the SSE stream
    job.download("model.hdf", "out/")  # sha256-checked
    sweep = c.submit_sweep(open("param.inp").read(), [{"t": 1.0}, {"t": 2.0}], max_parallel=4)
    rows = sweep.wait()                # one summary per row, with its parameter labels
"""
from .client import ApiError, Client, Job, Sweep, TransportError
from .sse import parse_sse

__all__ = ["ApiError", "Client", "Job", "Sweep", "TransportError", "parse_sse"]
