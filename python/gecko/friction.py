"""gecko.friction — public Python wrappers of the compiled friction kernels."""

__all__: list = []
