#!/usr/bin/env python3
"""Segments a map into rooms with topocut and draws them with matplotlib.

    python3 examples/segment_map.py maps/floorplan.yaml rooms.png [--concavity 2.5]

The map is a ROS map_server YAML or an image; the picture shows the rooms in colour over the map
(metres, map frame), each room's id at its inside point, doors in red and wider openings in orange.
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import topocut


def draw(m, result, path):
    h, w = m.grid.shape
    x0, y0 = m.origin[0], m.origin[1]
    extent = (x0, x0 + w * m.resolution, y0, y0 + h * m.resolution)
    # The map: free white, unknown grey, occupied black (row 0 at the origin, hence origin="lower").
    background = np.where(m.grid == 0, 1.0, np.where(m.grid < 0, 0.8, 0.0))
    fig, ax = plt.subplots(figsize=(8, 8 * h / w + 0.5))
    ax.imshow(background, cmap="gray", vmin=0, vmax=1, origin="lower", extent=extent, interpolation="nearest")
    rooms = np.ma.masked_equal(result.labels, 0)
    ax.imshow(rooms % 20, cmap="tab20", vmin=0, vmax=19, alpha=0.55, origin="lower", extent=extent, interpolation="nearest")
    for room in result.rooms:
        outline = np.vstack([room.outer, room.outer[:1]])
        ax.plot(outline[:, 0], outline[:, 1], color="black", linewidth=0.6)
        ax.text(*room.inside, str(room.id), ha="center", va="center", fontsize=8, weight="bold")
    for passage in result.passages:
        ax.plot(passage.cut[:, 0], passage.cut[:, 1], color="red" if passage.kind == "door" else "orange", linewidth=2)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    doors = sum(p.kind == "door" for p in result.passages)
    openings = len(result.passages) - doors

    def count(n, word):
        return f"{n} {word}" + ("" if n == 1 else "s")

    ax.set_title(f"{count(len(result.rooms), 'room')}, {count(doors, 'door')} (red), {count(openings, 'opening')} (orange)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("map", help="ROS map_server YAML or image")
    parser.add_argument("output", help="PNG to write")
    parser.add_argument("--concavity", type=float, default=2.5, help="maximum concavity tau in metres")
    args = parser.parse_args()
    m = topocut.load_map(args.map)
    result = topocut.segment(m.grid, m.resolution, m.origin, concavity=args.concavity)
    for room in result.rooms:
        print(f"room {room.id}: {room.area:.1f} m2 at ({room.inside[0]:.2f}, {room.inside[1]:.2f})")
    draw(m, result, args.output)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
