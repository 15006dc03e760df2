"""Stub of paraview.servermanager (tests only; see __init__.py)."""


def Fetch(source):
    raise RuntimeError("stub: no data to fetch")  # the script falls back to bounds and ranges
