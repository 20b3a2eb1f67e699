# facetlight in a container: Debian 12 with the package list of scripts/deps, built and tested at image build
# time, serving on 0.0.0.0:8080 (inside the container; publish it with `docker run -p 127.0.0.1:8080:8080`).
FROM debian:12
WORKDIR /src
COPY scripts/deps scripts/deps
RUN bash -c 'source scripts/deps && facetlight_install_deps "${FACETLIGHT_BUILD_DEPS[@]}" python3' \
    && rm -rf /var/lib/apt/lists/*
COPY . .
RUN rm -rf build && cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release \
    && cmake --build build --parallel "$(nproc)" \
    && cd build && ctest --output-on-failure --parallel "$(nproc)" --timeout 900 -LE browser
RUN useradd --system --create-home facetlight && mkdir -p /data && chown facetlight /data
USER facetlight
EXPOSE 8080
VOLUME /data
CMD ["/src/build/bin/facetlight-server", "--host", "0.0.0.0", "--port", "8080", "--data", "/data", \
     "--meshes", "/src/meshes", "--web", "/src/web"]
