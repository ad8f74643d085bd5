"""2D detection: what each camera image shows, before any view is joined to another."""
