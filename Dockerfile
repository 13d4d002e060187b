# The workbench GUI on 0.0.0.0:8080 (python slim, non-root).
FROM python:3.11-slim

ENV PIP_NO_CACHE_DIR=1 PYTHONDONTWRITEBYTECODE=1 PYTHONUNBUFFERED=1
RUN useradd --create-home --uid 1000 workbench
WORKDIR /app
COPY pyproject.toml README.md ./
COPY workbench ./workbench
COPY projects ./projects
COPY web_assets ./web_assets
COPY schema ./schema
RUN pip install . && chown -R workbench:workbench /app

USER workbench
EXPOSE 8080
CMD ["workbench", "serve", "projects/mz07_cell.json", "--host", "0.0.0.0", "--port", "8080", "--allow-dir", "web_assets"]
