# mechdyn: machine-dynamics calculation service.
# Build: docker build -t mechdyn .   Run: docker run -p 8080:8080 -v mechdyn-data:/data mechdyn
FROM rust:1-bookworm AS builder
SHELL ["/bin/bash", "-o", "pipefail", "-c"]
WORKDIR /src
COPY Cargo.toml Cargo.lock ./
# The dependencies in a layer of their own, built against an empty crate (and
# empty benchmarks: cargo reads the manifest's [[bench]] files): a change under
# src/ or benches/ rebuilds mechdyn alone (docs/operators.md, "Container").
RUN mkdir src benches && echo 'fn main() {}' > src/main.rs && touch src/lib.rs \
    && awk '/^\[\[bench\]\]/ { b = 1 } b && $1 == "name" { gsub(/"/, "", $3); print $3; b = 0 }' Cargo.toml \
        | while read -r name; do echo 'fn main() {}' > "benches/$name.rs"; done \
    && cargo build --release --locked --bin mechdyn \
    && rm -rf src target/release/mechdyn target/release/deps/mechdyn-* target/release/deps/libmechdyn-* \
        target/release/.fingerprint/mechdyn-*
COPY src ./src
COPY migrations ./migrations
# The built-in templates (the problem library) are compiled in.
COPY library ./library
RUN cargo build --release --locked --bin mechdyn \
    && mkdir -p /data

FROM gcr.io/distroless/cc-debian12:nonroot
COPY --from=builder /src/target/release/mechdyn /app/mechdyn
COPY --from=builder --chown=65532:65532 /data /data
ENV MECHDYN_ADDR=0.0.0.0:8080 \
    MECHDYN_OPERATOR_ADDR=0.0.0.0:9464 \
    DATABASE_URL=sqlite:///data/mechdyn.db \
    RUST_LOG=info
USER 65532:65532
EXPOSE 8080 9464
VOLUME ["/data"]
HEALTHCHECK --interval=30s --timeout=3s --start-period=5s CMD ["/app/mechdyn", "healthcheck"]
ENTRYPOINT ["/app/mechdyn"]
