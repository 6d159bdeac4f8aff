#!/usr/bin/python3
"""topocut_node on the loopback only: a private rosmaster on a free port of 127.0.0.1, the node, and
this script publishing maps with rospy and checking what comes back.

1. A Bormann map as one OccupancyGrid: the labels equal the library's (topocut_node_reference) cell
   for cell, in the map's row order and header; the graph is the library's rooms JSON; the markers
   show one outline and one id per room and one line per passage.
2. A growing sequence (the map revealed around a start cell, frame growing with new size and
   origin): labels and graph equal the library's incremental result for the same grids, room ids
   stay stable (churn between consecutive maps).
3. Malformed maps (data size not width x height, zero resolution) are logged and skipped; the node
   lives on and answers the next good map.
4. The typed rooms (rooms/rooms, topocut_msgs/Rooms) say what the rooms JSON says, for every map.
5. ~room_at (/topocut/room_at) finds each room at its inside point, and nothing off the map or in a wall.
6. ~segment_map (/topocut/segment_map) on the bundled map and on every real map of ../shared/datasets/real_maps and
   real_maps_gt (skipped with a message when absent): labels equal `topocut segment --out-labels`
   cell for cell and the JSON equals `--out-json` byte for byte; a bad option and a malformed map
   come back as an error, as do options the command line refuses (hexadecimal, given twice) and
   room_at at a point that is not a number; room_at still answers from the published rooms
   (segment_map is a what-if).
7. `topocut_node --help` prints the parameters and exits 0 while the node runs, which lives on; a bad
   parameter value stops a second node with the reason and exit 1; an unknown name is warned about; a
   second node under another name serves its own private services and leaves the first node's alone.
8. The action ~map_segmentation answers a goal with ~segment_map's rooms, labels and JSON, and the
   labels as a grid; its feedback names the stages in order; a bad option, and every option
   ~segment_map refuses, aborts the goal with the reason; like segment_map it is a what-if (room_at
   still answers from the published rooms).
9. rooms/grid (nav_msgs/OccupancyGrid) holds the labels on the map's grid (-1 no room, else the id),
   and the node logs its topics, services, action and parameters at start and one line per map.
10. Settling: a node left without a new map for ~settle_after publishes the rooms of segment_map
   (`topocut segment`) on the latest map, ids carried (timing kind "settled"); with ~id_ledger, a
   restarted node gives the same map the same ids.
The first runs use ~settle_after 0, so that their rooms are the library's incremental result.
Prints the node's latency (map received -> rooms published) beside the library's update time.
Every wait is bounded; the master and the node are stopped whatever happens. Exit 77: skipped.
"""
import argparse
import json
import os
import shutil
import signal
import socket
import statistics
import struct
import subprocess
import sys
import tempfile
import threading
import time

TIMEOUT = 20.0  # seconds for any one answer


def free_port():
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_for(condition, what, timeout=TIMEOUT):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if condition():
            return
        time.sleep(0.01)
    raise AssertionError("timed out waiting for " + what)


def stop(process):
    if process is None or process.poll() is not None:
        return
    os.killpg(process.pid, signal.SIGINT)
    try:
        process.wait(5)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        process.wait(5)


def private_master(rosmaster, work):
    """A rosmaster on a free port of 127.0.0.1, its logs in work, once it answers; returns it and the
    environment that points a process at it (os.environ is pointed at it too)."""
    port = free_port()
    env = dict(os.environ, ROS_MASTER_URI="http://127.0.0.1:%d" % port, ROS_IP="127.0.0.1",
               ROS_HOSTNAME="127.0.0.1", ROS_HOME=work, ROS_LOG_DIR=work)
    os.environ.update(env)
    master = subprocess.Popen([rosmaster, "--core", "-p", str(port)], env=env, start_new_session=True,
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        import rosgraph
        wait_for(lambda: rosgraph.is_master_online(), "rosmaster on port %d" % port)
    except BaseException:
        stop(master)
        raise
    return master, env


def read_grid(path):
    with open(path, "rb") as f:
        header = f.readline().split()
        width, height = int(header[1]), int(header[2])
        return {"width": width, "height": height, "resolution": float(header[3]),
                "x": float(header[4]), "y": float(header[5]), "values": f.read()}


def write_grid(path, g):
    with open(path, "wb") as f:
        f.write(("topocut-grid %d %d %r %r %r\n" % (g["width"], g["height"], g["resolution"], g["x"], g["y"])).encode())
        f.write(g["values"])


def growing_sequence(full, steps):
    """The map revealed within a growing radius of its most central free cell; the frame is the
    revealed box plus a margin, rounded to 40 cells (ROS maps grow in chunks)."""
    w, h, v = full["width"], full["height"], full["values"]
    free = [i for i in range(w * h) if v[i] == 0]
    cx = sum(i % w for i in free) // len(free)
    cy = sum(i // w for i in free) // len(free)
    start = min(free, key=lambda i: (i % w - cx) ** 2 + (i // w - cy) ** 2)
    sx, sy = start % w, start // w
    radius_max = max(w, h)
    grids = []
    for k in range(1, steps + 1):
        r = radius_max * k // steps
        x0, x1 = max(0, (sx - r - 10) // 40 * 40), min(w, ((sx + r + 10) // 40 + 1) * 40)
        y0, y1 = max(0, (sy - r - 10) // 40 * 40), min(h, ((sy + r + 10) // 40 + 1) * 40)
        out = bytearray()
        for y in range(y0, y1):
            row = v[y * w + x0:y * w + x1]
            dy2 = (y - sy) ** 2
            out += bytes(row[i] if (x0 + i - sx) ** 2 + dy2 <= r * r else 255 for i in range(len(row)))
        grids.append({"width": x1 - x0, "height": y1 - y0, "resolution": full["resolution"],
                      "x": full["x"] + x0 * full["resolution"], "y": full["y"] + y0 * full["resolution"],
                      "values": bytes(out)})
    return grids


def occupancy_grid_message(g, seq, frame="map"):
    """The grid as a nav_msgs/OccupancyGrid stamped 1000 + seq s (the stamp names the answer)."""
    import rospy
    from nav_msgs.msg import OccupancyGrid
    m = OccupancyGrid()
    m.header.frame_id = frame
    m.header.stamp = rospy.Time(1000 + seq)
    m.info.width, m.info.height, m.info.resolution = g["width"], g["height"], g["resolution"]
    m.info.origin.position.x, m.info.origin.position.y = g["x"], g["y"]
    m.info.origin.orientation.w = 1.0
    m.data = list(struct.unpack("%db" % len(g["values"]), g["values"]))
    return m


def percentile95(values):
    """The nearest-rank 95th percentile."""
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(0.95 * len(ordered) + 0.999) - 1)]


def churn(a, b):
    """Share of the cells labelled in both grids (matched through their origins) whose id changed."""
    res = a["resolution"]
    dx = round((b["x"] - a["x"]) / res)
    dy = round((b["y"] - a["y"]) / res)
    both = changed = 0
    la, lb = a["labels"], b["labels"]
    for y in range(b["height"]):
        ya = y + dy
        if not 0 <= ya < a["height"]:
            continue
        for x in range(b["width"]):
            xa = x + dx
            if not 0 <= xa < a["width"]:
                continue
            p, q = la[ya * a["width"] + xa], lb[y * b["width"] + x]
            if p and q:
                both += 1
                changed += p != q
    return changed / both if both else 0.0


def main():
    parser = argparse.ArgumentParser()
    for name in ("node", "reference", "rosmaster", "map", "cli", "source", "msgs"):
        parser.add_argument("--" + name, required=True)
    parser.add_argument("--time-limit", type=int, default=120, help="seconds for the whole test")
    parser.add_argument("--steps", type=int, default=8)
    args = parser.parse_args()
    if not os.path.exists(args.map):
        print("skipped: the Bormann map %s is not there" % args.map)
        return 77
    signal.alarm(args.time_limit)  # the whole test, whatever hangs
    sys.path.insert(0, args.msgs)  # topocut_msgs, generated by the build
    work = tempfile.mkdtemp(prefix="topocut_node_test_")
    master = None
    node_log = os.path.join(work, "node.log")
    try:
        subprocess.run([args.reference, "export", args.map, os.path.join(work, "full.grid")], check=True, timeout=60)
        full = read_grid(os.path.join(work, "full.grid"))
        grids = [full] + growing_sequence(full, args.steps)
        paths = []
        for k, g in enumerate(grids):
            paths.append(os.path.join(work, "grid_%d.grid" % k))
            write_grid(paths[-1], g)
        # The reference replays the full map first too, then resets for the sequence: run it twice.
        subprocess.run([args.reference, "replay", work, paths[0]], check=True, timeout=60)
        os.rename(os.path.join(work, "labels_0.u16"), os.path.join(work, "full_labels.u16"))
        os.rename(os.path.join(work, "rooms_0.json"), os.path.join(work, "full_rooms.json"))
        subprocess.run([args.reference, "replay", work] + paths[1:], check=True, timeout=60)

        master, env = private_master(args.rosmaster, work)
        result = run_checks(args, env, work, node_log, full, grids)
        shutil.rmtree(work, ignore_errors=True)  # kept only when a check failed, for its files and node.log
        return result
    finally:
        for process in node_holder:
            stop(process)
        stop(master)
        signal.alarm(0)


node_holder = []


def run_checks(args, env, work, node_log, full, grids):
    import rospy
    from nav_msgs.msg import OccupancyGrid
    from sensor_msgs.msg import Image
    from std_msgs.msg import String
    from visualization_msgs.msg import MarkerArray

    log = open(node_log, "wb")
    node = subprocess.Popen([args.node, "__name:=topocut", "_settle_after:=0"], env=env, start_new_session=True, stdout=log,
                            stderr=subprocess.STDOUT)
    node_holder.append(node)
    rospy.init_node("topocut_node_test", anonymous=True, disable_signals=True)
    from topocut_msgs.msg import Rooms
    received = {"labels": [], "markers": [], "graph": [], "timing": [], "rooms": [], "grid": []}
    rospy.Subscriber("/rooms/labels", Image, lambda m: received["labels"].append(m))
    rospy.Subscriber("/rooms/rooms", Rooms, lambda m: received["rooms"].append(m))
    rospy.Subscriber("/rooms/markers", MarkerArray, lambda m: received["markers"].append(m))
    rospy.Subscriber("/rooms/graph", String, lambda m: received["graph"].append(m))
    rospy.Subscriber("/rooms/timing", String, lambda m: received["timing"].append(m))
    rospy.Subscriber("/rooms/grid", OccupancyGrid, lambda m: received["grid"].append(m))
    publisher = rospy.Publisher("/map", OccupancyGrid, queue_size=10, latch=True)
    wait_for(lambda: publisher.get_num_connections() > 0, "the node to subscribe to /map")
    # The node's publishers must have connected to our subscribers before we publish.
    wait_for(lambda: "/topocut" in [n for n in rosnode_names()], "the node to register")
    time.sleep(0.5)

    def publish_and_wait(m):
        stamp = m.header.stamp
        counts = {k: len(v) for k, v in received.items()}
        publisher.publish(m)
        wait_for(lambda: any(x.header.stamp == stamp for x in received["labels"][counts["labels"]:]) and
                 any(x.header.stamp == stamp for x in received["rooms"][counts["rooms"]:]) and
                 len(received["graph"]) > counts["graph"] and len(received["markers"]) > counts["markers"] and
                 len(received["timing"]) > counts["timing"] and
                 any(x.header.stamp == stamp for x in received["grid"][counts["grid"]:]), "rooms for map stamp %s" % stamp.secs)
        labels = [x for x in received["labels"][counts["labels"]:] if x.header.stamp == stamp][-1]
        check_grid([x for x in received["grid"][counts["grid"]:] if x.header.stamp == stamp][-1], m, labels)
        typed = [x for x in received["rooms"][counts["rooms"]:] if x.header.stamp == stamp][-1]
        check_typed(typed, json.loads(received["graph"][-1].data), "map stamp %s" % stamp.secs)
        return labels, received["markers"][-1], received["graph"][-1], json.loads(received["timing"][-1].data)

    def check_rooms(g, labels, markers, graph, reference_labels, reference_json, what):
        assert labels.encoding == "16UC1" and labels.is_bigendian == 0, what
        assert (labels.width, labels.height, labels.step) == (g["width"], g["height"], 2 * g["width"]), what
        assert labels.header.frame_id == "map", what
        assert bytes(labels.data) == reference_labels, what + ": labels differ from the library's"
        if graph.data.encode() != reference_json:
            with open(os.path.join(work, "node_graph.json"), "w") as f:
                f.write(graph.data)
        assert graph.data.encode() == reference_json, what + ": graph differs from the library's rooms JSON (node_graph.json in " + work + ")"
        ids = set(struct.unpack("<%dH" % (len(labels.data) // 2), bytes(labels.data))) - {0}
        rooms = json.loads(graph.data)
        assert {r["id"] for r in rooms["rooms"]} == ids, what + ": graph rooms are not the label ids"
        for p in rooms["passages"]:
            assert set(p["rooms"]) <= ids, what + ": a passage names a room that is not there"
        by_ns = {}
        for mk in markers.markers:
            by_ns.setdefault(mk.ns, []).append(mk)
        assert markers.markers[0].action == 3, what + ": markers do not start with DELETEALL"
        assert {mk.id for mk in by_ns.get("outlines", [])} == ids, what + ": one outline per room"
        assert {int(mk.text) for mk in by_ns.get("ids", [])} == ids, what + ": one id text per room"
        assert all(mk.header.frame_id == "map" for mk in markers.markers[1:]), what
        assert len(by_ns["passages"][0].points) == 2 * len(rooms["passages"]), what + ": one line per passage"
        return ids

    def read(path):
        with open(path, "rb") as f:
            return f.read()

    latencies, updates = [], []
    # 1. The whole map at once.
    labels, markers, graph, timing = publish_and_wait(occupancy_grid_message(full, 0))
    ids = check_rooms(full, labels, markers, graph, read(os.path.join(work, "full_labels.u16")),
                      read(os.path.join(work, "full_rooms.json")), "full map")
    print("full map %d x %d: %d rooms, node callback %.2f ms, library update %.2f ms" %
          (full["width"], full["height"], len(ids), timing["callback_ms"], timing["update_ms"]))
    check_room_at(json.loads(graph.data), labels.header, full)
    check_node_log(node_log, full, len(ids))
    check_node_arguments(args, env, work, node)

    # 3a. Malformed maps between the two runs: logged, skipped, the node lives on.
    bad = occupancy_grid_message(full, 1)
    bad.data = bad.data[:-1]
    publisher.publish(bad)
    zero = occupancy_grid_message(full, 2)
    zero.info.resolution = 0.0
    time.sleep(0.3)
    publisher.publish(zero)
    wait_for(lambda: log_has(node_log, b"holds") and log_has(node_log, b"resolution"), "the node to log both bad maps")
    assert node.poll() is None, "the node died on a malformed map"

    # 2. A fresh node state is needed for the sequence to match the reference's fresh segmenter:
    # restart the node (as a robot starting a new map would).
    stop(node)
    node = subprocess.Popen([args.node, "__name:=topocut", "_settle_after:=0"], env=env, start_new_session=True, stdout=log,
                            stderr=subprocess.STDOUT)
    node_holder.append(node)
    wait_for(lambda: publisher.get_num_connections() > 0, "the restarted node to subscribe to /map")
    time.sleep(0.5)
    previous = None
    churns = []
    for k, g in enumerate(grids[1:]):
        labels, markers, graph, timing = publish_and_wait(occupancy_grid_message(g, 10 + k))
        check_rooms(g, labels, markers, graph, read(os.path.join(work, "labels_%d.u16" % k)),
                    read(os.path.join(work, "rooms_%d.json" % k)), "growing map %d" % k)
        latencies.append(timing["callback_ms"])
        updates.append(timing["update_ms"])
        current = dict(g, labels=struct.unpack("<%dH" % (len(labels.data) // 2), bytes(labels.data)))
        if previous is not None:
            churns.append(churn(previous, current))
        previous = current
    assert node.poll() is None
    last = json.loads(graph.data)["rooms"][0]
    published = (last["inside"], last["id"], labels.header.stamp)
    check_action(*check_segment_map(args, work, published), published)
    assert node.poll() is None
    # Ids are carried across updates: the node's labels are the library's byte for byte (check_rooms),
    # whose updates of this sequence are batch runs (each growth changes the frame) with ids kept by
    # overlap; batch's own churn on them is 14-48 % (how calm the library's ids are is tested in
    # tests/segmentation/incremental/incremental_batch_test.cpp). Fresh ids for every cell would give 100 %.
    assert max(churns) <= 0.5, "churn %s" % churns
    print("growing sequence of %d maps: churn per update %s" % (len(grids) - 1, ", ".join("%.4f" % c for c in churns)))
    p95 = percentile95(latencies)
    up95 = percentile95(updates)
    print("node latency (map received -> rooms published): median %.2f ms, p95 %.2f ms; library update median %.2f ms, "
          "p95 %.2f ms; ratio of p95s %.1f" % (statistics.median(latencies), p95, statistics.median(updates), up95,
                                               p95 / up95 if up95 > 0 else float("inf")))
    stop(node)
    check_settling(args, env, work, log, grids, publisher, received)
    print("ros_node_test: all checks passed")
    return 0


def close(a, b, what, tolerance=1e-4):
    """Typed coordinates are float32 (geometry_msgs/Point32) or the JSON's rounded metres."""
    assert abs(a - b) <= tolerance * max(1.0, abs(b)), "%s: %r against %r" % (what, a, b)


def check_typed(typed, rooms, what):
    """The typed rooms (topocut_msgs/Rooms) say what the rooms JSON says."""
    assert [r.id for r in typed.rooms] == [r["id"] for r in rooms["rooms"]], what + ": typed room ids"
    for r, j in zip(typed.rooms, rooms["rooms"]):
        name = "%s, room %d" % (what, j["id"])
        close(r.area, j["area"], name + " area", 1e-6)
        assert r.kind == (r.CORRIDOR if j["kind"] == "corridor" else r.ROOM), name + ": kind"
        for point, expected in ((r.centre, j["centroid"]), (r.inside, j["inside"])):
            close(point.x, expected[0], name), close(point.y, expected[1], name)
        assert len(r.outline.points) == len(j["outer"]) and len(r.holes) == len(j["holes"]), name + ": outline"
        for p, q in zip(r.outline.points, j["outer"]):
            close(p.x, q[0], name + " outline"), close(p.y, q[1], name + " outline")
        xs, ys = [q[0] for q in j["outer"]], [q[1] for q in j["outer"]]
        close(r.min.x, min(xs), name), close(r.min.y, min(ys), name), close(r.max.x, max(xs), name), close(r.max.y, max(ys), name)
    assert len(typed.passages) == len(rooms["passages"]), what + ": typed passages"
    for p, j in zip(typed.passages, rooms["passages"]):
        assert [p.room_a, p.room_b] == j["rooms"] and p.rule == j["rule"], what + ": passage rooms, rule"
        assert p.kind == (p.DOOR if j["kind"] == "door" else p.OPENING), what + ": passage kind"
        close(p.width, j["width"], what + " passage width", 1e-6)
        for point, expected in ((p.a, j["cut"][0]), (p.b, j["cut"][1])):
            close(point.x, expected[0], what), close(point.y, expected[1], what)


def room_at(x, y):
    import rospy
    from topocut_msgs.srv import RoomAt
    from geometry_msgs.msg import Point
    rospy.wait_for_service("/topocut/room_at", TIMEOUT)
    return rospy.ServiceProxy("/topocut/room_at", RoomAt)(Point(x, y, 0.0))


def check_room_at(rooms, header, grid):
    """Every room at its inside point, with its shape; nothing off the map or in a wall."""
    for r in rooms["rooms"]:
        answer = room_at(*r["inside"])
        assert answer.id == r["id"] and answer.room.id == r["id"], "room_at %s: %d, not %d" % (r["inside"], answer.id, r["id"])
        close(answer.room.area, r["area"], "room_at's room area", 1e-6)
        assert answer.header.stamp == header.stamp and answer.header.frame_id == header.frame_id, "room_at's header"
    assert room_at(grid["x"] - 1.0, grid["y"] - 1.0).id == 0, "room_at off the map"
    w = grid["width"]
    wall = next(i for i, v in enumerate(grid["values"]) if v == 100)
    answer = room_at(grid["x"] + (wall % w + 0.5) * grid["resolution"], grid["y"] + (wall // w + 0.5) * grid["resolution"])
    assert answer.id == 0 and answer.room.id == 0, "room_at in a wall"
    print("room_at: %d rooms found at their inside points, none off the map or in a wall" % len(rooms["rooms"]))


def shared_maps(source):
    """The bundled map, then every real map of the shared datasets that is there."""
    maps = [os.path.join(source, "maps", "floorplan.yaml")]
    for folder in ("real_maps", "real_maps_gt"):
        path = os.path.join(source, "..", "shared", "datasets", folder)
        if not os.path.isdir(path):
            print("skipped: %s is not there (segment_map = topocut segment on real maps unchecked)" % path)
            continue
        names = sorted(n for n in os.listdir(path) if n.endswith((".png", ".pgm", ".yaml")) and "_gt_" not in n)
        # A map_server PGM with its YAML is read through the YAML.
        maps += [os.path.join(path, n) for n in names if not (n.endswith(".pgm") and n[:-4] + ".yaml" in names)]
    return maps


# Options read as the command line reads them (no hexadecimal, no option twice, no 1 MB name echoed)
# and the reason each refusal must give, in one line: ~segment_map's and the action's goals alike.
REFUSED_OPTIONS = [(["concavity=0x10"], "~concavity needs a number, not '0x10'"),
                   (["concavity=2", "concavity=3"], "~concavity is given twice"),
                   (["x" * 100000 + "=1"], "is not a parameter of topocut_node")]


def segment_map(grid, options=(), stamp=0):
    import rospy
    from topocut_msgs.srv import SegmentMap
    rospy.wait_for_service("/topocut/segment_map", TIMEOUT)
    return rospy.ServiceProxy("/topocut/segment_map", SegmentMap)(occupancy_grid_message(grid, stamp), list(options))


def segment_map_against_cli(cli, reference, path, work, stamp):
    """path sent to ~segment_map (/topocut/segment_map) and segmented by `topocut segment`: the answer, the number of cells
    whose labels differ, whether the JSON is the same byte for byte, the call's round trip and the
    command's segmenting time (ms)."""
    import numpy
    from PIL import Image  # python3-pil, which python3-matplotlib brings
    grid_path = os.path.join(work, "static.grid")
    subprocess.run([reference, "export", path, grid_path], check=True, timeout=120)
    grid = read_grid(grid_path)
    start = time.monotonic()
    answer = segment_map(grid, stamp=stamp)
    call_ms = 1000 * (time.monotonic() - start)
    assert answer.error == "", "%s: segment_map: %s" % (path, answer.error)
    labels, rooms_json = os.path.join(work, "cli_labels.png"), os.path.join(work, "cli_rooms.json")
    out = subprocess.run([cli, "segment", path, "--out-labels", labels, "--out-json", rooms_json], check=True,
                         capture_output=True, text=True, timeout=120)
    with Image.open(labels) as image:
        expected = numpy.flipud(numpy.array(image)).astype("<u2")
    got = numpy.frombuffer(bytes(answer.labels.data), "<u2").reshape(answer.labels.height, answer.labels.width)
    assert got.shape == expected.shape, "%s: labels %s, the CLI's %s" % (path, got.shape, expected.shape)
    with open(rooms_json) as f:
        json_equal = answer.json == f.read()
    cli_ms = float(out.stdout.split(" ms (loading")[0].rsplit(" in ", 1)[1])
    return {"grid": grid, "answer": answer, "differ": int((got != expected).sum()), "json_equal": json_equal,
            "call_ms": call_ms, "cli_ms": cli_ms}


def check_segment_map(args, work, published):
    """The service's rooms are `topocut segment`'s: labels cell for cell, JSON byte for byte; the published
    rooms (published: a room's inside point, id and map stamp) stay what room_at answers from. Returns the
    first map's grid and answer."""
    counts, first_answer = [], None
    for k, path in enumerate(shared_maps(args.source)):
        name = os.path.basename(path)
        result = segment_map_against_cli(args.cli, args.reference, path, work, 500 + k)
        answer, grid = result["answer"], result["grid"]
        assert answer.labels.encoding == "16UC1" and answer.labels.header.stamp.secs == 1500 + k
        assert result["differ"] == 0, "%s: %d labelled cells differ from topocut segment's" % (name, result["differ"])
        assert result["json_equal"], "%s: segment_map's JSON differs from topocut segment --out-json" % name
        rooms = json.loads(answer.json)
        check_typed(answer.rooms, rooms, name)
        first = rooms["rooms"][0]
        at = room_at(*published[0])
        assert at.id == published[1] and at.header.stamp == published[2], name + ": room_at after segment_map"
        counts.append("%s %d" % (name, len(rooms["rooms"])))
        first_answer = first_answer or (grid, answer)
    print("segment_map = topocut segment (labels, JSON) on %d maps; rooms: %s" % (len(counts), ", ".join(counts)))
    answer = segment_map(grid, ["concavty=3"])
    assert "did you mean ~concavity?" in answer.error and not answer.rooms.rooms, answer.error
    answer = segment_map(grid, ["door_width=-1"])
    assert "~door_width must lie in" in answer.error, answer.error
    for options, reason in REFUSED_OPTIONS:
        answer = segment_map(grid, options)
        assert reason in answer.error and len(answer.error) <= 200 and not answer.rooms.rooms, answer.error[:300]
    answer = room_at(float("nan"), 0.0)
    assert answer.id == 0 and "finite coordinates" in answer.error, "room_at(nan): %r" % answer.error
    bad = dict(grid, values=grid["values"][:-1])
    answer = segment_map(bad)
    assert "values for" in answer.error, answer.error
    print("segment_map refuses: %s" % answer.error)
    return first_answer


def check_action(grid, expected, published):
    """~map_segmentation (/topocut/map_segmentation): a goal's result is ~segment_map's answer for the
    same map (labels, JSON, and the labels as a grid); its feedback, read on the action's feedback topic
    (a client may drop feedback that comes after the result, which travels on another topic), names the
    three stages in order with growing progress; a bad option, and every option ~segment_map refuses,
    aborts the goal with the reason. A what-if like segment_map: the published rooms (published: a room's
    inside point, id and map stamp) stay what room_at answers from."""
    import actionlib
    import rospy
    from actionlib_msgs.msg import GoalStatus
    from topocut_msgs.msg import MapSegmentationAction, MapSegmentationActionFeedback, MapSegmentationGoal
    feedback = []
    subscriber = rospy.Subscriber("/topocut/map_segmentation/feedback", MapSegmentationActionFeedback, feedback.append)
    client = actionlib.ActionClient("/topocut/map_segmentation", MapSegmentationAction)
    assert client.wait_for_server(rospy.Duration(TIMEOUT)), "no action server /topocut/map_segmentation"
    wait_for(lambda: subscriber.get_num_connections() > 0, "the action's feedback topic")
    sent = occupancy_grid_message(grid, 700)

    def run(options):
        done = threading.Event()
        handle = client.send_goal(MapSegmentationGoal(map=sent, options=options),
                                  lambda h: h.get_comm_state() == actionlib.CommState.DONE and done.set())
        assert done.wait(TIMEOUT), "no result for the goal %s" % options
        return handle

    handle = run([])
    result = handle.get_result()
    assert handle.get_goal_status() == GoalStatus.SUCCEEDED and result.error == "", handle.get_goal_status_text()
    assert result.json == expected.json, "the action's JSON differs from segment_map's"
    assert bytes(result.labels.data) == bytes(expected.labels.data), "the action's labels differ from segment_map's"
    check_grid(result.grid, sent, result.labels)
    at = room_at(*published[0])
    assert at.id == published[1] and at.header.stamp == published[2], "room_at after map_segmentation"
    goal_id = handle.comm_state_machine.action_goal.goal_id.id
    mine = lambda: [f.feedback for f in feedback if f.status.goal_id.id == goal_id]  # noqa: E731
    wait_for(lambda: len(mine()) == 3, "the goal's three feedback messages")
    stages = [(f.stage, f.progress) for f in mine()]
    assert [stage for stage, _ in stages] == ["accepted", "segmenting", "writing the result"], stages
    assert [p for _, p in stages] == sorted(p for _, p in stages) and 0 <= stages[0][1] and stages[-1][1] < 1, stages
    bad = run(["concavty=3"])
    assert bad.get_goal_status() == GoalStatus.ABORTED and "did you mean ~concavity?" in bad.get_result().error, \
        bad.get_result()
    for options, reason in REFUSED_OPTIONS:  # a goal's options pass the service's checks
        refused = run(options)
        error = refused.get_result().error
        assert refused.get_goal_status() == GoalStatus.ABORTED and reason in error and len(error) <= 200, error[:300]
    subscriber.unregister()
    print("map_segmentation: the result is segment_map's (%d rooms), feedback %s; a bad option aborts: %s" %
          (len(result.rooms.rooms), ", ".join("%s %.2f" % sp for sp in stages), bad.get_result().error))


def labels_of(message):
    return struct.unpack("<%dH" % (len(message.data) // 2), bytes(message.data))


def same_partition(a, b):
    forward, backward = {}, {}
    for x, y in zip(a, b):
        if (x == 0) != (y == 0) or forward.setdefault(x, y) != y or backward.setdefault(y, x) != x:
            return False
    return True


def check_settling(args, env, work, log, grids, publisher, received):
    """The growing sequence again to a node that settles after 0.5 s and keeps a ledger: at rest it publishes
    segment_map's rooms under the live ids; restarted, it gives the final map the same ids."""
    ledger = os.path.join(work, "ledger.txt")
    command = [args.node, "__name:=topocut", "_settle_after:=0.5", "_id_ledger:=" + ledger]

    def start():
        node = subprocess.Popen(command, env=env, start_new_session=True, stdout=log, stderr=subprocess.STDOUT)
        node_holder.append(node)
        wait_for(lambda: publisher.get_num_connections() > 0, "the settling node to subscribe to /map")
        time.sleep(0.5)
        return node

    def settled_after(count):
        return [json.loads(t.data)["kind"] for t in received["timing"][count:]].count("settled")

    def answers_to(stamp, start=0):
        return [m for m in received["labels"][start:] if m.header.stamp == stamp]

    node = start()
    first = len(received["labels"])
    for k, g in enumerate(grids[1:]):
        message = occupancy_grid_message(g, 100 + k)
        publisher.publish(message)
        # By the map's stamp: on a loaded machine the node may settle on an earlier map before this one
        # comes, and those labels (the earlier map's stamp) may arrive after it was sent.
        wait_for(lambda: answers_to(message.header.stamp, first), "rooms for map %d" % k)
    final = message.header.stamp
    live = labels_of(answers_to(final, first)[0])
    # The final map is answered twice: live, then settled (segment() on the whole map) once at rest.
    wait_for(lambda: len(answers_to(final, first)) == 2, "the node to settle")
    settled = labels_of(answers_to(final, first)[1])
    batch = labels_of(segment_map(grids[-1]).labels)
    assert same_partition(settled, batch), "the settled rooms are not segment_map's"
    kept = sum(1 for x, y in zip(live, settled) if x and x == y) / max(1, sum(1 for x in live if x))
    time.sleep(1.0)
    assert len(answers_to(final, first)) == 2, "the node settled twice without a new map"
    assert settled_after(0) >= 1, "no settled timing line"
    stop(node)
    assert os.path.exists(ledger), "no ledger written"
    node = start()
    count = len(received["labels"])
    publisher.publish(occupancy_grid_message(grids[-1], 200))
    wait_for(lambda: len(received["labels"]) > count, "rooms after the restart")
    assert labels_of(received["labels"][-1]) == settled, "a restarted node with the ledger gave other ids"
    stop(node)
    print("settling: segment_map's rooms after 0.5 s at rest (%.1f %% of the live labels kept their id); the same "
          "ids after a restart with ~id_ledger" % (100.0 * kept))


def check_node_arguments(args, env, work, node):
    """--help prints and exits without touching the running node; a bad value stops a node with the
    reason and exit 1; an unknown name is warned about, with the nearest known name."""
    help_out = subprocess.run([args.node, "--help"], env=env, capture_output=True, text=True, timeout=TIMEOUT)
    assert help_out.returncode == 0 and "_concavity:=M" in help_out.stdout and "_max_megapixels:=MP" in help_out.stdout, help_out
    time.sleep(0.5)
    assert node.poll() is None and "/topocut" in rosnode_names(), "--help shut the running node down"
    bad = subprocess.run([args.node, "__ns:=/other", "__name:=topocut_bad", "_concavity:=-1"], env=env, capture_output=True, text=True,
                         timeout=TIMEOUT)
    assert bad.returncode == 1 and "~concavity must lie in (0, 100000] metres, got -1" in bad.stdout + bad.stderr, bad
    typo_log = os.path.join(work, "typo.log")
    with open(typo_log, "wb") as log:
        # Beside the first node, in its namespace (no map reaches it): the case where shared service
        # names would be taken over.
        typo = subprocess.Popen([args.node, "__name:=topocut_typo", "map:=/topocut_test_no_map", "_concavty:=3"], env=env,
                                start_new_session=True,
                                stdout=log, stderr=subprocess.STDOUT)
    node_holder.append(typo)
    wait_for(lambda: log_has(typo_log, b"~concavty is not a parameter of topocut_node, ignored (did you mean ~concavity?)"),
             "the warning about ~concavty")
    # The services are the node's own: a second node answers under its name and takes nothing over.
    first_uri = service_uri("/topocut/segment_map")
    wait_for(lambda: service_uri("/topocut_typo/segment_map") is not None, "the second node's ~segment_map")
    assert service_uri("/topocut/segment_map") == first_uri != service_uri("/topocut_typo/segment_map"), \
        "a second node took over /topocut/segment_map"
    stop(typo)
    assert node.poll() is None and "/topocut" in rosnode_names()
    print("--help exits 0 and leaves the running node; ~concavity:=-1 is refused (exit 1); ~concavty is warned about; "
          "a second node's services are its own (/topocut_typo/segment_map)")


def service_uri(name):
    """The address of the node serving name, or None."""
    import rosgraph
    try:
        return rosgraph.Master("/topocut_node_test").lookupService(name)
    except rosgraph.MasterError:
        return None


def check_grid(grid, sent, labels):
    """rooms/grid: the map's header and metadata, -1 where the labels say no room, else the id."""
    assert grid.header.frame_id == sent.header.frame_id and (grid.info.width, grid.info.height) == (sent.info.width, sent.info.height) \
        and grid.info.origin == sent.info.origin, "rooms/grid's header or metadata"
    close(grid.info.resolution, sent.info.resolution, "rooms/grid's resolution (float32)", 1e-7)
    ids = struct.unpack("<%dH" % (len(labels.data) // 2), bytes(labels.data))
    expected = [-1 if i == 0 else 1 + (i - 1) % 100 for i in ids]
    assert list(grid.data) == expected, "rooms/grid differs from the labels"


def check_node_log(node_log, grid, rooms):
    """The start-up lines (topics, services, action, parameters) and the line of the map just segmented."""
    for needle in (b"maps from /map; rooms on /rooms/labels, /rooms/grid, /rooms/rooms",
                   b"services /topocut/segment_map, /topocut/room_at; action /topocut/map_segmentation",
                   b"parameters given: settle_after 0; defaults: concavity 2.5, robot_radius 0",
                   b"topocut_node: map %d x %d at %g m: %d rooms" % (grid["width"], grid["height"], grid["resolution"], rooms)):
        wait_for(lambda: log_has(node_log, needle), "the node to log %r" % needle)
    print("the node logs its names and parameters at start and one line per map")


def log_has(path, needle):
    with open(path, "rb") as f:
        return needle in f.read()


def rosnode_names():
    import rosgraph
    master = rosgraph.Master("/topocut_node_test")
    publishers, subscribers, _ = master.getSystemState()
    return {n for _, nodes in publishers + subscribers for n in nodes}


if __name__ == "__main__":
    sys.exit(main())
