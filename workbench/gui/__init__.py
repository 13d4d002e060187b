"""The browser GUI (viser): a thin adapter over `workbench.service`."""
