"""Generated sections of Markdown files: markers, and the README's pasted reports."""
