"""A stand-in for ParaView's Python package (tests only): enough of paraview.simple and
paraview.servermanager for open_in_paraview.py to run through without ParaView, recording what
it opened and checking that every file it opens exists (a .series file: every file it lists).
Not ParaView: whether ParaView accepts the properties set is not tested by this."""
