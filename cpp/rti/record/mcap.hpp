// A writer of MCAP files (https://mcap.dev/spec), the container of hlacore's recordings: JSON messages on
// topics with JSON schemas, in uncompressed chunks with their message indexes, and a summary (schemas,
// channels, statistics, chunk indexes) so that readers such as Foxglove seek instead of scanning. Chunks
// carry a CRC-32 of their records, which readers check.
//
// A full chunk goes to a thread of the writer's own, which computes its CRC and writes it out: in the
// gateway's loop those were a third of a recording gateway's CPU (docs/performance.md). At most kQueuedChunks wait
// for that thread; message() waits when they do, so memory stays bounded by a few chunks.
//
// Not thread-safe: one writer per file, called from one thread at a time. Written from the MCAP
// specification, no code of the reference implementation.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <map>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

namespace hlacore::mcap {

class Writer {
public:
    // Creates (truncates) `path` and writes the header; throws std::runtime_error naming the path when it
    // cannot. `profile` and `library` go into the header record.
    Writer(const std::string& path, std::string_view profile, std::string_view library);
    ~Writer();  // close()s, ignoring errors
    Writer(const Writer&) = delete;
    Writer& operator=(const Writer&) = delete;

    // The id of `topic`'s channel, registering the channel (and its schema, by name) the first time: JSON
    // messages described by the JSON schema `schema`.
    std::uint16_t channel(const std::string& topic, const std::string& schema_name, std::string_view schema);
    bool has_channel(const std::string& topic) const { return channel_ids_.count(topic) != 0; }
    std::uint16_t channel_id(const std::string& topic) const { return channel_ids_.at(topic); }

    // Appends a message to the current chunk; the chunk is written out when it reaches its size.
    void message(std::uint16_t channel, std::uint32_t sequence, std::uint64_t log_ns, std::string_view data);

    // Writes out the current chunk and waits until everything before it is in the file (a reader of a file
    // cut short after this sees it all); throws on a write error, this one or an earlier chunk's.
    void flush();
    // Writes out the current chunk, the summary and the footer, and closes the file; throws on a write error.
    void close();
    bool closed() const { return file_ == nullptr; }

    std::uint64_t messages() const { return message_count_; }
    std::uint64_t bytes_written() const { return offset_; }

private:
    struct Schema {
        std::uint16_t id;
        std::string name;
        std::string data;
    };
    struct Channel {
        std::uint16_t id;
        std::uint16_t schema;
        std::string topic;
    };
    struct ChunkIndex {
        std::uint64_t start_ns, end_ns, offset, length;
        std::map<std::uint16_t, std::uint64_t> index_offsets;
        std::uint64_t index_length;
        std::uint64_t size;
    };

    // A chunk record as the file thread gets it: its head (the CRC still to fill in), its records and the
    // message indexes that follow it.
    struct SealedChunk {
        std::string head, records, indexes;
    };

    static void put_schema(std::string& out, const Schema& schema);
    static void put_channel(std::string& out, const Channel& channel);
    void write(std::string_view bytes);  // on this thread (before the file thread starts, after it stops)
    void write_chunk();  // hands the current chunk to the file thread
    void wait_written(); // until the file thread has written all it was handed; throws its failure
    void stop_file_thread();
    void file_thread();
    std::string write_out(SealedChunk& chunk);  // on the file thread; "" or what went wrong
    std::string write_error() const;            // why the last write failed (errno), naming the file

    std::string path_;
    std::FILE* file_ = nullptr;
    std::uint64_t offset_ = 0;  // where the next record goes, counting what the file thread has still to write

    static constexpr std::size_t kQueuedChunks = 4;
    std::thread thread_;
    std::mutex mu_;  // guards what follows, shared with the file thread
    std::condition_variable changed_;
    std::deque<SealedChunk> queue_;
    bool writing_ = false, stopping_ = false;
    std::string failure_;               // the file thread's first write error; it writes nothing after it
    std::vector<std::string> spare_;    // emptied record buffers, their capacity kept for the next chunks

    std::vector<Schema> schemas_;
    std::map<std::string, std::uint16_t> schema_ids_;
    std::vector<Channel> channels_;
    std::map<std::string, std::uint16_t> channel_ids_;

    // The chunk being filled: its records, and per channel (log time, offset in `chunk_`) of each message.
    std::string chunk_;
    std::map<std::uint16_t, std::vector<std::pair<std::uint64_t, std::uint64_t>>> chunk_messages_;
    std::uint64_t chunk_start_ns_ = 0, chunk_end_ns_ = 0;
    std::vector<ChunkIndex> chunk_indexes_;

    std::uint64_t message_count_ = 0, start_ns_ = 0, end_ns_ = 0;
    std::map<std::uint16_t, std::uint64_t> channel_counts_;
};

// CRC-32 (ISO-HDLC), the checksum MCAP uses: zlib's crc32, continuing from `crc`.
std::uint32_t crc32(std::string_view bytes, std::uint32_t crc = 0);

}  // namespace hlacore::mcap
