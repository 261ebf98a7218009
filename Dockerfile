# mechdyn: machine-dynamics calculation service.
# Build: docker build -t mechdyn .   Run: docker run -p 8080:8080 -v mechdyn-data:/data mechdyn
FROM rust:1-bookworm AS builder
WORKDIR /src
COPY Cargo.toml Cargo.lock ./
COPY src ./src
COPY migrations ./migrations
# The built-in templates (the problem library) are compiled in.
COPY library ./library
# The manifest names the benchmarks: cargo cannot read it without their files.
COPY benches ./benches
RUN cargo build --release --locked --bin mechdyn \
    && mkdir -p /data

FROM gcr.io/distroless/cc-debian12:nonroot
COPY --from=builder /src/target/release/mechdyn /app/mechdyn
COPY --from=builder --chown=65532:65532 /data /data
ENV MECHDYN_ADDR=0.0.0.0:8080 \
    DATABASE_URL=sqlite:///data/mechdyn.db \
    RUST_LOG=info
USER 65532:65532
EXPOSE 8080
VOLUME ["/data"]
HEALTHCHECK --interval=30s --timeout=3s --start-period=5s CMD ["/app/mechdyn", "healthcheck"]
ENTRYPOINT ["/app/mechdyn"]
