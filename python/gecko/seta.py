"""gecko.seta — public Python wrappers of the compiled seta kernels."""

__all__: list = []
