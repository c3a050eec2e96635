"""The anchor of pac-sim's Modbus round trip (pacsim_bench): pymodbus's own TCP server on 127.0.0.1:PORT with 64
holding and 64 input registers at unit id 1, serving until it is terminated. Prints "ready" once it listens.

Usage: anchor_server.py PORT"""
import asyncio
import sys

from pymodbus.datastore import ModbusDeviceContext, ModbusSequentialDataBlock, ModbusServerContext
from pymodbus.server import ModbusTcpServer


async def serve(port):
    # pymodbus numbers a block from 1: protocol address 0 is the block at 1.
    device = ModbusDeviceContext(hr=ModbusSequentialDataBlock(1, [0] * 64), ir=ModbusSequentialDataBlock(1, [0] * 64))
    server = ModbusTcpServer(ModbusServerContext(devices={1: device}, single=False), address=("127.0.0.1", port))
    await server.serve_forever(background=True)
    print("ready", flush=True)
    await server.serving


def main():
    asyncio.run(serve(int(sys.argv[1])))


if __name__ == "__main__":
    main()
