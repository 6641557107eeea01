"""Python client for kontaktd, standard library only.

    from kontakt_client import Client
    c = Client("http://127.0.0.1:8080")
    job = c.submit_file("model.inp", name="run 1", labels={"sweep": "a"})
    final = job.wait()                 # polls; job.wait(stream=True) follows the SSE stream
    job.download("model.hdf", "out/")  # sha256-checked
"""
from .client import ApiError, Client, Job, TransportError
from .sse import parse_sse

__all__ = ["ApiError", "Client", "Job", "TransportError", "parse_sse"]
