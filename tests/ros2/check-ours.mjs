// Reads a ROS 2 bag swslam-rawlog2bag wrote (a rosbag2 folder or a single .mcap) with readers
// that are not swslam's: the MCAP project's indexed reader (@mcap/core: the summary, chunk
// indexes and message indexes our writer wrote), Foxglove's CDR reader (@foxglove/cdr), and
// checks that it holds the messages of a ROS 1 bag of the same log (read by @foxglove/rosbag):
// the same topics, types, counts and bag times, in log-time order, and every field swslam
// writes equal.
//
// Usage: node check-ours.mjs OURS REFERENCE.bag
import { CdrReader } from "@foxglove/cdr";
import { Bag } from "@foxglove/rosbag";
import { FileReader } from "@foxglove/rosbag/node.js";
import { McapIndexedReader } from "@mcap/core";
import fs from "node:fs";
import path from "node:path";

const [ours, reference] = process.argv.slice(2);
if (!ours || !reference) {
  console.error("usage: node check-ours.mjs (FOLDER | FILE.mcap) REFERENCE.bag");
  process.exit(2);
}
const TYPES = { "/scan": "sensor_msgs/msg/LaserScan", "/odom": "nav_msgs/msg/Odometry", "/tf_static": "tf2_msgs/msg/TFMessage" };
const fail = (what) => { console.error(`check-ours: ${ours}: ${what}`); process.exit(1); };

// ---- the rosbag2 folder's metadata.yaml (what `ros2 bag info` and the player read)
let file = ours;
if (fs.statSync(ours).isDirectory()) {
  const yaml = fs.readFileSync(path.join(ours, "metadata.yaml"), "utf8");
  if (!/storage_identifier: mcap/.test(yaml)) fail("metadata.yaml: no storage_identifier mcap");
  const files = [...yaml.matchAll(/relative_file_paths:\n((?:\s+- .*\n)+)/g)][0];
  if (!files) fail("metadata.yaml: no relative_file_paths");
  const names = files[1].trim().split("\n").map((l) => l.replace(/^\s*- /, ""));
  if (names.length !== 1) fail(`metadata.yaml lists ${names.length} files`);
  file = path.join(ours, names[0]);
  globalThis.metadataCount = Number(/\n  message_count: (\d+)/.exec(yaml)[1]);
}

// ---- the reference: the ROS 1 bag's messages, in time order
const ref = [];
{
  const reader = new FileReader(reference);
  const bag = new Bag(reader, { parse: true });
  await bag.open();
  for await (const m of bag.messageIterator({ topics: Object.keys(TYPES) }))
    ref.push({ topic: m.topic, timeNs: BigInt(m.timestamp.sec) * 1000000000n + BigInt(m.timestamp.nsec), msg: m.message });
  await reader.close();
}

// ---- ours, through the summary and indexes
const fd = fs.openSync(file, "r");
const readable = {
  size: async () => BigInt(fs.fstatSync(fd).size),
  read: async (offset, size) => {
    const buf = Buffer.alloc(Number(size));
    fs.readSync(fd, buf, 0, Number(size), Number(offset));
    return buf;
  },
};
const reader = await McapIndexedReader.Initialize({ readable });
if (reader.chunkIndexes.length === 0) fail("no chunk index in its summary");
if (!reader.statistics || reader.statistics.messageCount !== BigInt(ref.length))
  fail(`its statistics count ${reader.statistics?.messageCount} messages, the reference ${ref.length}`);
if (globalThis.metadataCount !== undefined && globalThis.metadataCount !== ref.length)
  fail(`metadata.yaml counts ${globalThis.metadataCount} messages, the reference ${ref.length}`);
for (const c of reader.channelsById.values()) {
  const schema = reader.schemasById.get(c.schemaId);
  if (c.messageEncoding !== "cdr" || schema?.name !== TYPES[c.topic] || schema?.encoding !== "ros2msg")
    fail(`channel ${c.topic}: ${c.messageEncoding}, schema ${schema?.name} (${schema?.encoding})`);
}

const header = (r) => ({ sec: r.int32(), nsec: r.uint32(), frame_id: r.string() });
const decode = {
  "/scan": (r) => {
    const m = { header: header(r) };
    for (const f of ["angle_min", "angle_max", "angle_increment", "time_increment", "scan_time", "range_min", "range_max"])
      m[f] = r.float32();
    m.ranges = r.float32Array();
    m.intensities = r.float32Array();
    return m;
  },
  "/odom": (r) => {
    const m = { header: header(r), child_frame_id: r.string() };
    m.pose = [r.float64(), r.float64(), r.float64(), r.float64(), r.float64(), r.float64(), r.float64()];
    return m;
  },
  "/tf_static": (r) => {
    const n = r.sequenceLength(), transforms = [];
    for (let i = 0; i < n; i++) {
      const t = { header: header(r), child_frame_id: r.string() };
      t.values = [r.float64(), r.float64(), r.float64(), r.float64(), r.float64(), r.float64(), r.float64()];
      transforms.push(t);
    }
    return { transforms };
  },
};
const same = (a, b, what) => { if (a !== b) throw new Error(`${what}: ${a} vs ${b}`); };
const sameHeader = (h, ros1, what) => {
  same(h.sec, ros1.stamp.sec, `${what} stamp sec`);
  same(h.nsec, ros1.stamp.nsec, `${what} stamp nsec`);
  same(h.frame_id, ros1.frame_id, `${what} frame_id`);
};
const pose7 = (p) => [p.position.x, p.position.y, p.position.z, p.orientation.x, p.orientation.y, p.orientation.z, p.orientation.w];
const tf7 = (t) => [t.translation.x, t.translation.y, t.translation.z, t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w];

// Messages of one time may come in either order: each topic's in turn, and all by log time.
const refOf = {};
for (const m of ref) (refOf[m.topic] ??= []).push(m);
let i = 0, lastTime = 0n;
const counts = {};
for await (const message of reader.readMessages()) {
  const topic = reader.channelsById.get(message.channelId).topic;
  const want = (refOf[topic] ?? [])[counts[topic] ?? 0];
  const what = `message ${i} (${topic} #${counts[topic] ?? 0})`;
  try {
    if (!want) throw new Error("more messages than the reference");
    if (message.logTime < lastTime) throw new Error("not in log-time order");
    lastTime = message.logTime;
    same(message.logTime, want.timeNs, `${what} log time`);
    const got = decode[topic](new CdrReader(message.data)), w = want.msg;
    if (topic === "/scan") {
      sameHeader(got.header, w.header, what);
      for (const f of ["angle_min", "angle_max", "angle_increment", "time_increment", "scan_time", "range_min", "range_max"])
        same(got[f], w[f], `${what} ${f}`);
      same(got.ranges.length, w.ranges.length, `${what} rays`);
      got.ranges.forEach((r, k) => same(Object.is(r, w.ranges[k]) || r === w.ranges[k], true, `${what} ray ${k}`));
      same(got.intensities.length, w.intensities.length, `${what} intensities`);
    } else if (topic === "/odom") {
      sameHeader(got.header, w.header, what);
      same(got.child_frame_id, w.child_frame_id, `${what} child_frame_id`);
      pose7(w.pose.pose).forEach((v, k) => same(got.pose[k], v, `${what} pose ${k}`));
    } else {
      same(got.transforms.length, w.transforms.length, `${what} transforms`);
      got.transforms.forEach((t, k) => {
        sameHeader(t.header, w.transforms[k].header, `${what} transform ${k}`);
        same(t.child_frame_id, w.transforms[k].child_frame_id, `${what} transform ${k} child`);
        tf7(w.transforms[k].transform).forEach((v, j) => same(t.values[j], v, `${what} transform ${k} value ${j}`));
      });
    }
  } catch (e) {
    fail(e.message);
  }
  counts[topic] = (counts[topic] ?? 0) + 1;
  i++;
}
if (i !== ref.length) fail(`${i} messages, the reference ${ref.length}`);
fs.closeSync(fd);
console.log(`check-ours: ${ours}: ${Object.entries(counts).map(([t, n]) => `${n} ${t}`).join(", ")} through ` +
  `${reader.chunkIndexes.length} chunk index(es), read by @mcap/core's indexed reader and @foxglove/cdr, equal ` +
  `the ROS 1 bag's, field for field`);
