"""Stub of paraview.simple (tests only; see __init__.py). OPENED lists the files opened."""
import json
import os

OPENED = []
LOG = []


class Proxy:
    """Accepts any property and any method call; records them in LOG."""

    def __init__(self, kind):
        self.__dict__["kind"] = kind
        self.__dict__["props"] = {}

    def __setattr__(self, name, value):
        self.props[name] = value
        LOG.append((self.kind, name, value))

    def __getattr__(self, name):
        if name in self.props:
            return self.props[name]

        def call(*args, **kwargs):
            LOG.append((self.kind, name, args))
            return Proxy(self.kind + "." + name)

        return call


class Source(Proxy):
    def __init__(self, path):
        Proxy.__init__(self, "source:" + os.path.basename(path))
        self.__dict__["PointData"] = {"radius": None, "broken_fraction": None, "plastic_strain": None,
                                      "von_mises_stress": None}

    def GetDataInformation(self):
        class Info:
            def GetBounds(self):
                return [0.0, 1e-3, 0.0, 1e-3, 0.0, 1e-3]
        return Info()


def OpenDataFile(path):
    if not os.path.exists(path):
        raise RuntimeError("stub OpenDataFile: no file " + path)
    if path.endswith(".series"):
        with open(path) as f:
            series = json.load(f)
        assert series["file-series-version"] == "1.0"
        for entry in series["files"]:
            member = os.path.join(os.path.dirname(path), entry["name"])
            if not os.path.exists(member):
                raise RuntimeError("stub OpenDataFile: %s lists %s, which does not exist" % (path, member))
            float(entry["time"])
    OPENED.append(path)
    return Source(path)


def _proxy(kind):
    def make(*args, **kwargs):
        LOG.append((kind, args, kwargs))
        return Proxy(kind)
    return make


def GetParaViewVersion():
    return "5.11"


for _name in ("AddCameraLink", "AnnotateTime", "AssignViewToLayout", "Calculator", "ColorBy", "CreateView", "GetActiveViewOrCreate",
              "GetAnimationScene", "GetColorTransferFunction", "GetLayout", "GetOpacityTransferFunction", "GetScalarBar", "Hide",
              "RenameSource", "Render", "SetActiveView", "Show"):
    globals()[_name] = _proxy(_name)


def SaveScreenshot(path, layout, ImageResolution=None):
    with open(path, "wb") as f:
        f.write(b"stub")
    LOG.append(("SaveScreenshot", path, ImageResolution))
