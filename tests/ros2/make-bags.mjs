// Writes ROS 2 bags with writers that are not swslam's own: MCAP files through the MCAP
// project's @mcap/core (chunks compressed by @foxglove/wasm-zstd or lz4js), CDR through
// Foxglove's @foxglove/cdr, .db3 files through the sqlite3 program, laid out as rosbag2 does
// (tables topics and messages; metadata.yaml).
//
// Usage: node make-bags.mjs SOURCE OUTDIR
//   SOURCE: a ROS 1 bag (read with @foxglove/rosbag: its /scan, /odom and /tf_static messages
//   are written again as ROS 2 messages, the same values and bag times), or "synthetic" (a
//   5-scan drive along a 10 m x 6 m room, its values documented in scenario.json).
// Writes into OUTDIR: zstd.mcap (zstd chunks), be.mcap (big-endian CDR, uncompressed chunks),
// unchunked.mcap (no chunks), lz4/ (a rosbag2 folder of one .mcap with lz4 chunks), db3/ (a
// rosbag2 folder of one .db3), db3-zstd/ (.db3, each message zstd-compressed, as rosbag2's
// compression_mode MESSAGE does), db3-file-zstd/ (the .db3 compressed whole: FILE),
// scenario.json (counts, first and last values), fuzz-seeds/.
import { CdrWriter, EncapsulationKind } from "@foxglove/cdr";
import { Bag } from "@foxglove/rosbag";
import { FileReader } from "@foxglove/rosbag/node.js";
import { McapWriter } from "@mcap/core";
import * as zstd from "@foxglove/wasm-zstd";
import lz4 from "lz4js";
import { spawnSync } from "node:child_process";
import fs from "node:fs";
import path from "node:path";

const [source, outDir] = process.argv.slice(2);
if (!source || !outDir) {
  console.error("usage: node make-bags.mjs (ROS1.bag | synthetic) OUTDIR");
  process.exit(2);
}

const TYPES = {
  "/scan": "sensor_msgs/msg/LaserScan",
  "/odom": "nav_msgs/msg/Odometry",
  "/tf_static": "tf2_msgs/msg/TFMessage",
};
const DEFINITIONS = {
  "sensor_msgs/msg/LaserScan":
    "std_msgs/Header header\nfloat32 angle_min\nfloat32 angle_max\nfloat32 angle_increment\nfloat32 time_increment\n" +
    "float32 scan_time\nfloat32 range_min\nfloat32 range_max\nfloat32[] ranges\nfloat32[] intensities\n",
  "nav_msgs/msg/Odometry":
    "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/PoseWithCovariance pose\n" +
    "geometry_msgs/TwistWithCovariance twist\n",
  "tf2_msgs/msg/TFMessage": "geometry_msgs/TransformStamped[] transforms\n",
};

// ---- the messages: { topic, timeNs (bigint), msg } in time order, msg in ROS 1 field names
async function fromRos1Bag(file) {
  const reader = new FileReader(file);
  const bag = new Bag(reader, { parse: true });
  await bag.open();
  const out = [];
  for await (const m of bag.messageIterator({ topics: Object.keys(TYPES) })) {
    const t = BigInt(m.timestamp.sec) * 1000000000n + BigInt(m.timestamp.nsec);
    out.push({ topic: m.topic, timeNs: t, msg: m.message });
  }
  await reader.close();
  return out;
}

function synthetic() {
  const rays = 181, step = Math.PI / (rays - 1), out = [];
  const stamp = (k) => ({ sec: 1000 + Math.floor(k / 10), nsec: (k % 10) * 100000000 });
  const tf = { header: { stamp: { sec: 999, nsec: 0 }, frame_id: "base_link" }, child_frame_id: "laser",
    transform: { translation: { x: 0.2, y: 0, z: 0.3 }, rotation: { x: 0, y: 0, z: 0, w: 1 } } };
  out.push({ topic: "/tf_static", timeNs: 999000000000n, msg: { transforms: [tf] } });
  for (let k = 0; k < 5; k++) {
    const x = -2 + 0.2 * k, sx = x + 0.2; // the robot and its laser, facing +x in a room [-5,5] x [-3,3]
    const ranges = new Float32Array(rays);
    for (let i = 0; i < rays; i++) {
      const a = -Math.PI / 2 + i * step, c = Math.cos(a), s = Math.sin(a);
      const tx = c > 1e-9 ? (5 - sx) / c : Infinity, ty = Math.abs(s) > 1e-9 ? 3 / Math.abs(s) : Infinity;
      ranges[i] = Math.min(tx, ty);
    }
    ranges[0] = NaN; // no return
    const t = stamp(k), timeNs = BigInt(t.sec) * 1000000000n + BigInt(t.nsec);
    out.push({ topic: "/odom", timeNs, msg: { header: { stamp: t, frame_id: "odom" }, child_frame_id: "base_link",
      pose: { pose: { position: { x, y: 0, z: 0 }, orientation: { x: 0, y: 0, z: 0, w: 1 } }, covariance: new Array(36).fill(0) },
      twist: { twist: { linear: { x: 2, y: 0, z: 0 }, angular: { x: 0, y: 0, z: 0 } }, covariance: new Array(36).fill(0) } } });
    out.push({ topic: "/scan", timeNs, msg: { header: { stamp: t, frame_id: "laser" }, angle_min: -Math.PI / 2,
      angle_max: Math.PI / 2, angle_increment: step, time_increment: 0, scan_time: 0.1, range_min: 0.05, range_max: 30,
      ranges, intensities: new Float32Array(0) } });
  }
  return out;
}

// ---- CDR (ROS 2 layouts: the header has no seq; stamps are int32 sec, uint32 nanosec)
function cdr(topic, msg, kind) {
  const w = new CdrWriter({ kind });
  const header = (h) => w.int32(h.stamp.sec).uint32(h.stamp.nsec).string(h.frame_id);
  const vec3 = (v) => w.float64(v.x).float64(v.y).float64(v.z);
  const quat = (q) => w.float64(q.x).float64(q.y).float64(q.z).float64(q.w);
  if (topic === "/scan") {
    header(msg.header);
    for (const f of ["angle_min", "angle_max", "angle_increment", "time_increment", "scan_time", "range_min", "range_max"])
      w.float32(msg[f]);
    w.float32Array(Array.from(msg.ranges), true).float32Array(Array.from(msg.intensities), true);
  } else if (topic === "/odom") {
    header(msg.header);
    w.string(msg.child_frame_id);
    vec3(msg.pose.pose.position); quat(msg.pose.pose.orientation);
    w.float64Array(Array.from(msg.pose.covariance), false);
    vec3(msg.twist.twist.linear); vec3(msg.twist.twist.angular);
    w.float64Array(Array.from(msg.twist.covariance), false);
  } else {
    w.sequenceLength(msg.transforms.length);
    for (const t of msg.transforms) {
      header(t.header);
      w.string(t.child_frame_id);
      vec3(t.transform.translation); quat(t.transform.rotation);
    }
  }
  return w.data;
}

// ---- MCAP through @mcap/core
async function writeMcap(file, messages, { compression = "", kind = EncapsulationKind.CDR_LE, useChunks = true } = {}) {
  const parts = [];
  let position = 0n;
  const writable = { write: async (b) => { parts.push(Buffer.from(b)); position += BigInt(b.byteLength); }, position: () => position };
  const compressChunk =
    compression === "zstd" ? (d) => ({ compression, compressedData: zstd.compress(d, 19) })
    : compression === "lz4" ? (d) => ({ compression, compressedData: Uint8Array.from(lz4.compress(d)) })
    : undefined;
  const writer = new McapWriter({ writable, useChunks, chunkSize: 64 * 1024, compressChunk });
  await writer.start({ profile: "ros2", library: "swslam make-bags.mjs (@mcap/core)" });
  const channels = {};
  for (const topic of Object.keys(TYPES)) {
    if (!messages.some((m) => m.topic === topic)) continue;
    const schemaId = await writer.registerSchema({ name: TYPES[topic], encoding: "ros2msg",
      data: new TextEncoder().encode(DEFINITIONS[TYPES[topic]]) });
    channels[topic] = await writer.registerChannel({ schemaId, topic, messageEncoding: "cdr", metadata: new Map() });
  }
  let sequence = 0;
  for (const m of messages)
    await writer.addMessage({ channelId: channels[m.topic], sequence: sequence++, logTime: m.timeNs,
      publishTime: m.timeNs, data: cdr(m.topic, m.msg, kind) });
  await writer.end();
  fs.writeFileSync(file, Buffer.concat(parts));
}

// ---- .db3 through the sqlite3 program
function writeDb3(file, messages, messageZstd) {
  const hex = (b) => Buffer.from(b).toString("hex");
  const topics = Object.keys(TYPES).filter((t) => messages.some((m) => m.topic === t));
  let sql = "PRAGMA journal_mode=OFF;\nBEGIN;\n" +
    "CREATE TABLE schema(schema_version INTEGER PRIMARY KEY, ros_distro TEXT NOT NULL);\n" +
    "INSERT INTO schema VALUES (3, 'humble');\n" +
    "CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL, " +
    "serialization_format TEXT NOT NULL, offered_qos_profiles TEXT NOT NULL);\n" +
    "CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL, timestamp INTEGER NOT NULL, " +
    "data BLOB NOT NULL);\nCREATE INDEX timestamp_idx ON messages (timestamp ASC);\n";
  topics.forEach((t, i) => { sql += `INSERT INTO topics VALUES (${i + 1}, '${t}', '${TYPES[t]}', 'cdr', '');\n`; });
  for (const m of messages) {
    let data = cdr(m.topic, m.msg, EncapsulationKind.CDR_LE);
    if (messageZstd) data = zstd.compress(data, 3);
    sql += `INSERT INTO messages(topic_id, timestamp, data) VALUES (${topics.indexOf(m.topic) + 1}, ${m.timeNs}, X'${hex(data)}');\n`;
  }
  sql += "COMMIT;\n";
  fs.rmSync(file, { force: true });
  const r = spawnSync("sqlite3", [file], { input: sql, maxBuffer: 1 << 30 });
  if (r.status !== 0) throw new Error(`sqlite3 failed (${r.status}): ${r.stderr}`);
}

function writeFolder(dir, storage, fileName, messages, compression = "", mode = "MESSAGE") {
  fs.rmSync(dir, { recursive: true, force: true });
  fs.mkdirSync(dir, { recursive: true });
  const counts = Object.keys(TYPES).map((t) => [t, messages.filter((m) => m.topic === t).length]).filter(([, n]) => n > 0);
  const first = messages[0].timeNs, last = messages[messages.length - 1].timeNs;
  const yaml = [
    "rosbag2_bagfile_information:",
    "  version: 5",
    `  storage_identifier: ${storage}`,
    "  duration:",
    `    nanoseconds: ${last - first}`,
    "  starting_time:",
    `    nanoseconds_since_epoch: ${first}`,
    `  message_count: ${messages.length}`,
    "  topics_with_message_count:",
    ...counts.flatMap(([t, n]) => [
      "    - topic_metadata:", `        name: ${t}`, `        type: ${TYPES[t]}`,
      "        serialization_format: cdr", "        offered_qos_profiles: \"\"", `      message_count: ${n}`]),
    `  compression_format: "${compression}"`,
    `  compression_mode: "${compression ? mode : ""}"`,
    "  relative_file_paths:",
    `    - ${fileName}${mode === "FILE" ? ".zstd" : ""}`,
    "",
  ].join("\n");
  fs.writeFileSync(path.join(dir, "metadata.yaml"), yaml);
  return path.join(dir, fileName);
}

function summary(messages) {
  const on = (t) => messages.filter((m) => m.topic === t);
  const scans = on("/scan"), odom = on("/odom"), tf = on("/tf_static");
  const scanOf = (m) => ({ stamp: m.msg.header.stamp, rays: m.msg.ranges.length, range0: m.msg.ranges[0],
    rangeLast: m.msg.ranges[m.msg.ranges.length - 1], frame: m.msg.header.frame_id });
  const odomOf = (m) => ({ stamp: m.msg.header.stamp, x: m.msg.pose.pose.position.x, y: m.msg.pose.pose.position.y });
  return { scans: scans.length, odometry: odom.length, tf_static: tf.length,
    first_scan: scanOf(scans[0]), last_scan: scanOf(scans[scans.length - 1]),
    first_odometry: odomOf(odom[0]), last_odometry: odomOf(odom[odom.length - 1]),
    mounting: tf.length ? tf[0].msg.transforms.map((t) => ({ parent: t.header.frame_id, child: t.child_frame_id,
      x: t.transform.translation.x, y: t.transform.translation.y, z: t.transform.translation.z })) : [] };
}

await zstd.isLoaded;
const messages = source === "synthetic" ? synthetic() : await fromRos1Bag(source);
if (!messages.some((m) => m.topic === "/scan")) throw new Error(`${source}: no /scan message`);
fs.mkdirSync(outDir, { recursive: true });
await writeMcap(path.join(outDir, "zstd.mcap"), messages, { compression: "zstd" });
await writeMcap(path.join(outDir, "be.mcap"), messages, { kind: EncapsulationKind.CDR_BE });
await writeMcap(path.join(outDir, "unchunked.mcap"), messages, { useChunks: false });
await writeMcap(writeFolder(path.join(outDir, "lz4"), "mcap", "lz4_0.mcap", messages), messages, { compression: "lz4" });
writeDb3(writeFolder(path.join(outDir, "db3"), "sqlite3", "db3_0.db3", messages), messages, false);
writeDb3(writeFolder(path.join(outDir, "db3-zstd"), "sqlite3", "db3-zstd_0.db3", messages, "zstd"), messages, true);
const whole = writeFolder(path.join(outDir, "db3-file-zstd"), "sqlite3", "db3-file-zstd_0.db3", messages, "zstd", "FILE");
writeDb3(whole, messages, false);
fs.writeFileSync(whole + ".zstd", zstd.compress(fs.readFileSync(whole), 3));
fs.rmSync(whole);
fs.writeFileSync(path.join(outDir, "scenario.json"), JSON.stringify(summary(messages), null, 1) + "\n");
// The fuzz harnesses' seeds (tests/fuzz/ros2_bag_fuzz.cpp, cdr_messages_fuzz.cpp): the MCAP
// files, and each message type in both byte orders behind its type byte.
const seeds = path.join(outDir, "fuzz-seeds");
fs.mkdirSync(path.join(seeds, "ros2_bag"), { recursive: true });
fs.mkdirSync(path.join(seeds, "cdr_messages"), { recursive: true });
for (const f of ["zstd.mcap", "be.mcap", "unchunked.mcap", "lz4/lz4_0.mcap"])
  fs.copyFileSync(path.join(outDir, f), path.join(seeds, "ros2_bag", path.basename(f)));
Object.keys(TYPES).forEach((topic, type) => {
  const m = messages.find((x) => x.topic === topic);
  if (!m) return;
  for (const [name, kind] of [["le", EncapsulationKind.CDR_LE], ["be", EncapsulationKind.CDR_BE]])
    fs.writeFileSync(path.join(seeds, "cdr_messages", `${topic.slice(1)}-${name}`),
      Buffer.concat([Buffer.from([type]), cdr(topic, m.msg, kind)]));
});
console.log(`make-bags: ${messages.length} messages from ${source} -> ${outDir}`);
