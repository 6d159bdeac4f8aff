"""topocut: segment 2-D robot maps into rooms.

    import topocut
    m = topocut.load_map("maps/floorplan.yaml")           # int8 grid, ROS row order
    r = topocut.segment(m.grid, m.resolution, m.origin)   # options: help(topocut.segment)
    r.labels, r.rooms, r.passages                          # numpy labels; rooms, passages in metres
    r.room_at(2.0, 1.5)                                    # the Room at a point of the map frame, or None
    r.to_json(), r.to_geojson()                            # what --out-json / --out-geojson write
    r.to_shapely(), r.to_networkx()                        # with python3-shapely / python3-networkx
    s = topocut.evaluate("X_labels.png", "X_gt_segmentation.png", free="X.png")
    s.recall, s.precision, s.f1, s.pq, s.segments_per_room
    robot_map, rooms = topocut.simulate_map("X.png", "X_gt_segmentation.png", seed=3)  # robot-made map

Bad input raises ValueError with the message the topocut command prints; a file that is missing or
cannot be opened raises FileNotFoundError, PermissionError or IsADirectoryError; an unknown keyword
TypeError. Results (Segmentation, Room, Passage, Map, Scores) can be pickled.
"""
import inspect as _inspect
import typing as _typing

from . import _topocut
from ._topocut import (
    Map,
    Passage,
    Room,
    Scores,
    Segmentation,
    __version__,
    ale,
    decompose,
    evaluate,
    extract_lines,
    iepf,
    load_map,
    load_options,
    lt,
    merge_feature_names,
    segmentation_rules,
    sef,
    smf,
)

__all__ = [
    "IncrementalSegmenter", "Map", "Passage", "Room", "Scores", "Segmentation", "ale", "decompose", "evaluate",
    "extract_lines", "iepf", "load_map", "load_options", "lt", "merge_feature_names", "merge_training_rows", "segment",
    "segmentation_rules", "sef", "simulate_map", "smf",
]

_TYPES = {"bool": bool, "int": int, "float": float, "str": str, "str | None": _typing.Optional[str]}


def _with_keywords(function, kind, positional):
    """Gives function the signature `positional, *, <keywords of kind>` (the option table's names,
    types and defaults), so that help(), inspect and editors show every option."""
    parameters = list(positional)
    parameters += [
        _inspect.Parameter(name, _inspect.Parameter.KEYWORD_ONLY, default=default, annotation=_TYPES[type_name])
        for name, type_name, default, _help in _topocut._keywords(kind)
    ]
    function.__signature__ = _inspect.Signature(parameters)
    lines = [f"    {name}: {help_text} (default {default!r})" for name, _type, default, help_text in _topocut._keywords(kind)]
    function.__doc__ = (function.__doc__ or "") + "\n\nKeyword options:\n" + "\n".join(lines)
    return function


def _positional(name, default=_inspect.Parameter.empty):
    return _inspect.Parameter(name, _inspect.Parameter.POSITIONAL_OR_KEYWORD, default=default)


_GRID = [_positional("grid"), _positional("resolution", 0.05), _positional("origin", (0.0, 0.0, 0.0))]


def segment(grid, resolution=0.05, origin=(0.0, 0.0, 0.0), **options):
    return _topocut.segment(grid, resolution, origin, **options)


segment.__doc__ = _topocut.segment.__doc__.split("\n", 1)[1].strip()
_with_keywords(segment, "segment", _GRID)


def merge_training_rows(image, ground_truth, resolution=0.05, **options):
    return _topocut.merge_training_rows(image, ground_truth, resolution, **options)


merge_training_rows.__doc__ = _topocut.merge_training_rows.__doc__.split("\n\n", 1)[1].strip()
_with_keywords(merge_training_rows, "options", [_positional("image"), _positional("ground_truth"), _positional("resolution", 0.05)])


_SEED = _topocut._keywords("seed")[0][2]  # simulate-map's --seed row


def simulate_map(plan, ground_truth, seed=_SEED, resolution=0.05, **options):
    return _topocut.simulate_map(plan, ground_truth, seed, resolution, **options)


simulate_map.__doc__ = _topocut.simulate_map.__doc__.split("\n\n", 1)[1].strip()
_with_keywords(simulate_map, "simulate",
               [_positional("plan"), _positional("ground_truth"), _positional("seed", _SEED), _positional("resolution", 0.05)])


class IncrementalSegmenter(_topocut.IncrementalSegmenter):
    __doc__ = _topocut.IncrementalSegmenter.__doc__

    def __init__(self, **options):
        super().__init__(**options)

    def update(self, grid, resolution=0.05, origin=(0.0, 0.0, 0.0), **reading):
        return super().update(grid, resolution, origin, **reading)

    update.__doc__ = _topocut.IncrementalSegmenter.update.__doc__.split("\n", 1)[1].strip()


_with_keywords(IncrementalSegmenter.__init__, "incremental", [_positional("self")])
_with_keywords(IncrementalSegmenter.update, "grid", [_positional("self")] + _GRID)


def _needs(module, package):
    try:
        return __import__(module, fromlist=["_"])
    except ImportError as e:
        raise ImportError(f"this needs {module}: apt-get install {package} (or pip install {module})") from e


def _room_to_shapely(self):
    """The room as a shapely Polygon (map frame, metres; outer ring and holes). Needs shapely."""
    geometry = _needs("shapely.geometry", "python3-shapely")
    return geometry.Polygon(self.outer, self.holes)


def _passage_to_shapely(self):
    """The passage's cut as a shapely LineString (map frame, metres). Needs shapely."""
    geometry = _needs("shapely.geometry", "python3-shapely")
    return geometry.LineString(self.cut)


def _segmentation_to_shapely(self):
    """{room id: shapely Polygon} of every room (map frame, metres); the passages' cuts are
    [p.to_shapely() for p in result.passages]. Needs shapely."""
    return {room.id: room.to_shapely() for room in self.rooms}


def _segmentation_to_networkx(self):
    """The room graph as a networkx MultiGraph: a node per room id (attributes kind, area, labelled_area,
    centroid, inside, bbox, room) and an edge per passage (attributes kind, width, cut, passage);
    two rooms joined by two doors have two edges. Needs networkx."""
    networkx = _needs("networkx", "python3-networkx")
    graph = networkx.MultiGraph()
    for room in self.rooms:
        graph.add_node(room.id, kind=room.kind, area=room.area, labelled_area=room.labelled_area, centroid=room.centroid,
                       inside=room.inside, bbox=room.bbox, room=room)
    for passage in self.passages:
        graph.add_edge(*passage.rooms, kind=passage.kind, width=passage.width, cut=passage.cut, passage=passage)
    return graph


Room.to_shapely = _room_to_shapely
Passage.to_shapely = _passage_to_shapely
Segmentation.to_shapely = _segmentation_to_shapely
Segmentation.to_networkx = _segmentation_to_networkx

# The classes are topocut.X to their users (repr, help, pickle), not topocut._topocut.X.
for _class in (Map, Passage, Room, Scores, Segmentation):
    _class.__module__ = __name__
del _class
