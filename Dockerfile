# The workbench GUI on 0.0.0.0:8080 (python slim, non-root).
# Without a project the page opens the project picker (the examples and an upload);
# "Save as" writes in the working folder /home/workbench/projects.
FROM python:3.11-slim

ENV PIP_NO_CACHE_DIR=1 PYTHONDONTWRITEBYTECODE=1 PYTHONUNBUFFERED=1
# Open CASCADE (OCP, for STEP files) links libGL and libX11 even without a display.
RUN apt-get update && apt-get install -y --no-install-recommends libgl1 \
    && rm -rf /var/lib/apt/lists/*
RUN useradd --create-home --uid 1000 workbench
WORKDIR /app
COPY pyproject.toml README.md ./
COPY workbench ./workbench
COPY projects ./projects
COPY web_assets ./web_assets
COPY schema ./schema
# A non-editable install: the examples and their meshes go to <prefix>/share/workbench
# (pyproject.toml's data-files), where the picker finds them.
RUN pip install . && rm -rf /app/build \
    && mkdir -p /home/workbench/projects && chown workbench:workbench /home/workbench/projects

USER workbench
WORKDIR /home/workbench/projects
EXPOSE 8080
# /healthz answers "ok" without the access token and reveals nothing else.
HEALTHCHECK --interval=30s --timeout=5s --start-period=20s --retries=3 \
    CMD ["python", "-c", "import urllib.request,sys; sys.exit(0 if urllib.request.urlopen('http://127.0.0.1:8080/healthz', timeout=4).read() == b'ok\\n' else 1)"]
CMD ["workbench", "serve", "--host", "0.0.0.0", "--port", "8080"]
